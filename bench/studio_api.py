#!/usr/bin/env python3
"""`g2d studio`'s server side of a keystroke: POST /api/run for every example
at its default size, the fastest of --repeat round trips (HTTP on loopback,
compile, derive, SVG, the 3D model, JSON), and the server's own "ms".
Prints one Markdown row per example, then the median and the worst.
The page's side (parse, draw) is measured in the browser by bench/studio_keystroke.mjs.
Usage: python3 bench/studio_api.py [--g2d build/release/bin/g2d] [--repeat 3]
"""
import argparse
import glob
import http.client
import json
import os
import signal
import statistics
import subprocess
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ap = argparse.ArgumentParser()
ap.add_argument("--g2d", default=os.path.join(root, "build/release/bin/g2d"))
ap.add_argument("--repeat", type=int, default=3)
args = ap.parse_args()

studio = subprocess.Popen([args.g2d, "studio", "--port", "0"], cwd=os.path.join(root, "examples"), stdout=subprocess.PIPE, text=True)
port = int(studio.stdout.readline().strip().rsplit(":", 1)[1].rstrip("/"))
headers = {"Content-Type": "application/json", "Host": f"127.0.0.1:{port}"}
print("| example | status | steps | elements | SVG bytes | server ms | round trip ms |")
print("|---|---|---|---|---|---|---|")
trips = []
try:
    for path in sorted(glob.glob(os.path.join(root, "examples", "*.g2d"))):
        body = json.dumps({"text": open(path).read(), "timeout": 30})
        best = None
        for _ in range(args.repeat):
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
            began = time.perf_counter()
            conn.request("POST", "/api/run", body, headers)
            res = conn.getresponse()
            reply = json.loads(res.read())
            trip = (time.perf_counter() - began) * 1000
            conn.close()
            if best is None or trip < best[0]:
                best = (trip, res.status, reply)
        trip, status, reply = best
        trips.append(trip)
        elements = sum(reply.get("elements", {}).values())
        print(f"| {os.path.basename(path)} | {status} | {reply.get('steps', '')} | {elements} | {len(reply.get('svg', ''))} "
              f"| {reply.get('ms', 0):.1f} | {trip:.1f} |")
finally:
    studio.send_signal(signal.SIGINT)
    studio.wait(10)
print(f"\nround trip: median {statistics.median(trips):.1f} ms, worst {max(trips):.1f} ms over {len(trips)} examples")
