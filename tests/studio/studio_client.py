"""A `g2d studio` for a test: start it, send it JSON, read its answers."""
import http.client
import json
import subprocess
import sys


def start(g2d, args, cwd):
    """The studio process and its port, read from the URL on its first line."""
    proc = subprocess.Popen([g2d, "studio", *args], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    url = proc.stdout.readline().strip()
    if not url.startswith("http://127.0.0.1:") or not url.endswith("/"):
        proc.kill()
        sys.exit(f"FAIL: the first line is not the URL: {url!r} {proc.stderr.read()}")
    return proc, int(url.rsplit(":", 1)[1].rstrip("/"))


def post(port, path, body, timeout=60):
    """(status, parsed JSON, or {} when the answer is not JSON) of a POST of `body` as JSON, sent as the page sends it."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    conn.request("POST", path, json.dumps(body), {"Content-Type": "application/json"})
    res = conn.getresponse()
    text = res.read().decode()
    conn.close()
    try:
        return res.status, json.loads(text)
    except ValueError:
        return res.status, {}


def stop(proc):
    """Ends the studio with SIGINT, as a person would; its exit code."""
    proc.send_signal(2)
    try:
        return proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        return None
