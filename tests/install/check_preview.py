"""Runs `crtc --preview SCRIPT` as a user would and checks that the page gets an image.

    check_preview.py CRTC SCRIPT [crtc option]...

The first line crtc prints is the preview's URL; its state must show a rendered image and no
errors (an installed crtc-preview that found the standard library and the image encoder),
frame.png must be a PNG, and the page's quit must end crtc with status 0. Exits 1 with the
reason otherwise.
"""
import json
import subprocess
import sys
import time
import urllib.parse
import urllib.request


def fail(message, process):
    process.kill()
    sys.exit(f"check_preview: {message}; crtc's errors: {process.stderr.read()!r}")


def main():
    crtc, script, *options = sys.argv[1:]
    process = subprocess.Popen([crtc, "--preview", script, *options], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    if not line.startswith("preview: http://127.0.0.1:"):
        fail(f"the first line is {line!r}, not the preview's URL", process)
    url = urllib.parse.urlsplit(line.split(" ", 1)[1].strip())
    base, token = f"http://{url.netloc}", urllib.parse.parse_qs(url.query)["token"][0]

    def get(path):
        with urllib.request.urlopen(f"{base}{path}?token={token}", timeout=10) as reply:
            return reply.read()

    deadline = time.monotonic() + 120
    state = json.loads(get("/api/state"))
    while state["image"] == 0 and state["errors"] == 0 and time.monotonic() < deadline:
        time.sleep(0.1)
        state = json.loads(get("/api/state"))
    if state["errors"] != 0:
        fail(f"the preview reports errors: {state['diagnostics']!r}", process)
    if state["image"] == 0:
        fail("no image within 120 s", process)
    if not get("/api/frame.png").startswith(b"\x89PNG\r\n\x1a\n"):
        fail("/api/frame.png is not a PNG", process)
    request = urllib.request.Request(f"{base}/api/quit?token={token}", data=b"{}", method="POST",
                                     headers={"Content-Type": "application/json"})
    urllib.request.urlopen(request, timeout=10).read()
    try:
        status = process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        fail("crtc did not stop within 30 s of the page's quit", process)
    if status != 0:
        fail(f"crtc ended with status {status} after the page's quit", process)


main()
