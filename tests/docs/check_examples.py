#!/usr/bin/env python3
"""Runs every crtc transcript in the docs and compares it with crtc's real output.

A transcript is a ```text block whose lines start with "$ crtc": each command is run in a
fresh folder holding the ```crt blocks that came before it in the same page (a block whose
first line is "-- name.crt" is that file, others are scene.crt) and a copy of demos/, and
what it prints (standard output and error, as a terminal user sees them) must be the lines
that follow it. Times and ray rates vary from run to run and are compared as placeholders.
A transcript preceded by "<!-- transcript not checked: REASON -->" is skipped, with its reason.

usage: check_examples.py REPOSITORY CRTC [DOC.md ...]
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\w*)\s*$")
SKIP = re.compile(r"<!-- transcript not checked: (.+?) -->")
VARYING = [
    (re.compile(r"\d+\.\d+ Mrays/s"), "<rate> Mrays/s"),
    (re.compile(r"\d+\.\d+s\b"), "<time>s"),
    (re.compile(r"peak \d+\.\d+ MiB"), "peak <memory> MiB"),
]
PROGRESS = re.compile(r"^crtc: (frame .*)?\d+% \(\d+\.\d+s\)$")


def blocks(text):
    """(language, lines, skip reason or None) of each fenced block, in order."""
    lines = text.split("\n")
    i, reason = 0, None
    while i < len(lines):
        skip = SKIP.search(lines[i])
        if skip:
            reason = skip.group(1)
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        end = i + 1
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        yield m.group(1), lines[i + 1:end], reason
        reason = None
        i = end + 1


def normalise(text):
    lines = [line.rstrip() for line in text.rstrip("\n").split("\n") if not PROGRESS.match(line)]
    for pattern, placeholder in VARYING:
        lines = [pattern.sub(placeholder, line) for line in lines]
    return lines


def transcript_commands(lines):
    """(command, expected output lines) pairs of a transcript."""
    commands = []
    for line in lines:
        if line.startswith("$ "):
            commands.append((line[2:], []))
        elif commands:
            commands[-1][1].append(line)
    return commands


def run(command, crtc, folder):
    shell = re.sub(r"(^|\|\s*)crtc\b", lambda m: m.group(1) + crtc, command)
    try:
        result = subprocess.run(["bash", "-c", shell], cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, timeout=120, env=dict(os.environ, NO_COLOR="1"))
    except subprocess.TimeoutExpired:
        return "(did not finish within 120 s)"
    # The pages show the folder as /tmp/scenes and the standard library where it is installed.
    return (result.stdout.replace(os.path.realpath(folder), "/tmp/scenes").replace(folder, "/tmp/scenes")
            .replace(os.path.join(REPOSITORY, "stdlib"), "/usr/share/crt/stdlib"))


def check_page(path, repository, crtc):
    failures, checked, skipped = [], 0, []
    scripts = {}
    with open(path, encoding="utf-8") as f:
        page = f.read()
    for language, lines, reason in blocks(page):
        if language == "crt":
            name = lines[0][3:].strip() if lines and re.match(r"^-- [\w/.-]+\.crt$", lines[0]) else "scene.crt"
            scripts[name] = "\n".join(lines) + "\n"
            continue
        if language != "text" or not lines or not lines[0].startswith("$ crtc"):
            continue
        if reason:
            skipped.append(f"{lines[0]} ({reason})")
            continue
        for command, expected in transcript_commands(lines):
            tool = re.search(r"\|\s*(\w+)", command)
            if tool and not shutil.which(tool.group(1)):
                skipped.append(f"$ {command} (needs {tool.group(1)}, not installed)")
                continue
            with tempfile.TemporaryDirectory() as folder:
                for name, text in scripts.items():
                    os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
                    with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                        f.write(text)
                shutil.copytree(os.path.join(repository, "demos"), os.path.join(folder, "demos"))
                actual = normalise(run(command, crtc, folder))
            checked += 1
            if actual != normalise("\n".join(expected)):
                failures.append((command, expected, actual))
    return failures, checked, skipped


REPOSITORY = ""


def main():
    global REPOSITORY
    repository, crtc = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    REPOSITORY = repository
    pages = sys.argv[3:] or sorted(
        os.path.join(repository, "docs", name) for name in os.listdir(os.path.join(repository, "docs"))
        if name.endswith(".md"))
    total_failures, total_checked = 0, 0
    for page in pages:
        failures, checked, skipped = check_page(page, repository, crtc)
        total_checked += checked
        for reason in skipped:
            print(f"{os.path.basename(page)}: skipped {reason}")
        for command, expected, actual in failures:
            total_failures += 1
            print(f"FAIL: {os.path.basename(page)}: $ {command}")
            print("  documented:\n" + "\n".join("    " + line for line in expected))
            print("  actual:\n" + "\n".join("    " + line for line in actual))
    print(f"{total_checked} transcripts checked, {total_failures} differ")
    return 1 if total_failures else 0


if __name__ == "__main__":
    sys.exit(main())
