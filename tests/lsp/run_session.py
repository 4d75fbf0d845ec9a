#!/usr/bin/env python3
"""Runs a scripted JSON-RPC session against the real crt-lsp binary.

usage: run_session.py CRT_LSP SESSION.json

A session is a JSON object: {"args": [...], "steps": [...]}. Steps, in order:
  {"send": MESSAGE}          send a JSON-RPC message ("jsonrpc": "2.0" is added)
  {"raw": "TEXT"}            send bytes as they are (to test framing errors)
  {"expect": MESSAGE}        take the next response (when MESSAGE has an "id"), or the next
                             notification with the same "method" (and params.version and
                             params.uri, when given), and check that it matches MESSAGE;
                             messages passed over wait for later steps
  {"exit": CODE}             close stdin and wait for the server to exit with CODE
Matching is by subset: objects match when every expected member matches; lists match
element-wise with the same length, unless written {"$contains": [...]} (each expected item
matches some item) or {"$length": N}; {"$any": true} matches anything, {"$absent": true} a
missing member, and {"$regex": "..."} a string.
Strings "$URI" and "$DIR" are replaced by the session document's URI and folder; a text
{"$repeat": "TEXT", "times": N} is expanded, and {"$join": [TEXT, ...]} joins its texts.
"""
import atexit
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import queue
import time

TIMEOUT = 20.0


def substitute(value, env):
    if isinstance(value, str):
        for key, replacement in env.items():
            value = value.replace(key, replacement)
        return value
    if isinstance(value, list):
        return [substitute(v, env) for v in value]
    if isinstance(value, dict):
        if "$repeat" in value and "times" in value:
            return substitute(value["$repeat"], env) * value["times"]
        if "$join" in value:
            return "".join(substitute(value["$join"], env))
        return {substitute(k, env): substitute(v, env) for k, v in value.items()}
    return value


def matches(expected, actual, path="$"):
    """None when `actual` matches `expected`, else a description of the first difference."""
    if isinstance(expected, dict):
        if expected.get("$any"):
            return None
        if "$regex" in expected:
            if isinstance(actual, str) and re.search(expected["$regex"], actual):
                return None
            return f"{path}: {actual!r} does not match /{expected['$regex']}/"
        if "$contains" in expected:
            if not isinstance(actual, list):
                return f"{path}: expected a list, got {actual!r}"
            for item in expected["$contains"]:
                if all(matches(item, a) is not None for a in actual):
                    return f"{path}: no item matches {json.dumps(item)}"
            return None
        if "$length" in expected:
            if isinstance(actual, list) and len(actual) == expected["$length"]:
                return None
            return f"{path}: expected {expected['$length']} items, got {actual!r}"
        if not isinstance(actual, dict):
            return f"{path}: expected an object, got {actual!r}"
        for key, value in expected.items():
            if isinstance(value, dict) and value.get("$absent"):
                if key in actual:
                    return f"{path}.{key}: expected no member, got {actual[key]!r}"
                continue
            if key not in actual:
                return f"{path}.{key}: missing in {json.dumps(actual)[:300]}"
            problem = matches(value, actual[key], f"{path}.{key}")
            if problem:
                return problem
        return None
    if isinstance(expected, list):
        if not isinstance(actual, list) or len(actual) != len(expected):
            return f"{path}: expected {json.dumps(expected)[:300]}, got {json.dumps(actual)[:300]}"
        for i, (e, a) in enumerate(zip(expected, actual)):
            problem = matches(e, a, f"{path}[{i}]")
            if problem:
                return problem
        return None
    if expected != actual:
        return f"{path}: expected {expected!r}, got {actual!r}"
    return None


def reader(stream, messages):
    while True:
        headers = {}
        while True:
            line = stream.readline()
            if not line:
                messages.put(None)
                return
            line = line.decode("ascii", "replace").strip()
            if not line:
                break
            name, _, value = line.partition(":")
            headers[name.strip().lower()] = value.strip()
        length = int(headers.get("content-length", "0"))
        body = stream.read(length)
        messages.put(json.loads(body.decode("utf-8")))


def main():
    lsp, session_path = sys.argv[1], sys.argv[2]
    with open(session_path, encoding="utf-8") as f:
        session = json.load(f)
    workdir = tempfile.mkdtemp(prefix="crt-lsp-session-")
    atexit.register(shutil.rmtree, workdir, ignore_errors=True)  # also after a failed step
    document = os.path.join(workdir, "scene.crt")
    for name, text in session.get("files", {}).items():
        with open(os.path.join(workdir, name), "w", encoding="utf-8") as f:
            f.write(text)
    env = {"$URI": "file://" + document, "$DIR": workdir}
    process = subprocess.Popen([lsp] + session.get("args", []), stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, stderr=sys.stderr, cwd=workdir)
    messages = queue.Queue()
    threading.Thread(target=reader, args=(process.stdout, messages), daemon=True).start()

    def write(data):
        process.stdin.write(data)
        process.stdin.flush()

    def fail(message):
        print(f"{os.path.basename(session_path)}: {message}", file=sys.stderr)
        process.kill()
        sys.exit(1)

    backlog = []
    for number, step in enumerate(substitute(session["steps"], env), 1):
        if "send" in step:
            body = json.dumps(dict({"jsonrpc": "2.0"}, **step["send"])).encode("utf-8")
            write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        elif "raw" in step:
            write(step["raw"].encode("utf-8"))
        elif "expect" in step:
            expected = step["expect"]
            deadline = time.monotonic() + TIMEOUT

            def candidate(message):
                if "id" in expected and "method" not in expected:
                    return "id" in message and "method" not in message
                if message.get("method") != expected.get("method"):
                    return False
                version = expected.get("params", {}).get("version")
                uri = expected.get("params", {}).get("uri")
                params = message.get("params", {})
                return (version is None or params.get("version") == version) and \
                    (uri is None or params.get("uri") == uri)

            found = None
            for i, message in enumerate(backlog):
                if candidate(message):
                    found = backlog.pop(i)
                    break
            while found is None:
                try:
                    message = messages.get(timeout=max(0.0, deadline - time.monotonic()))
                except queue.Empty:
                    fail(f"step {number}: timed out waiting for {json.dumps(expected)[:300]}")
                if message is None:
                    fail(f"step {number}: the server closed its output")
                if candidate(message):
                    found = message
                else:
                    backlog.append(message)  # a later step may expect it
            message = found
            if "id" in expected and message.get("id") != expected["id"]:
                fail(f"step {number}: got the response {json.dumps(message)[:300]}, expected id {expected['id']}")
            problem = matches(expected, message)
            if problem:
                fail(f"step {number}: {problem}\n  the message: {json.dumps(message)[:2000]}")
        elif "exit" in step:
            process.stdin.close()
            try:
                code = process.wait(timeout=TIMEOUT)
            except subprocess.TimeoutExpired:
                fail("the server did not exit")
            if code != step["exit"]:
                fail(f"exit code {code}, expected {step['exit']}")
        elif "comment" in step:
            pass
        else:
            fail(f"step {number}: unknown step {step}")
    if process.poll() is None:
        process.kill()
    print(f"{os.path.basename(session_path)}: ok")


if __name__ == "__main__":
    main()
