#!/usr/bin/env python3
"""Drives a running `simhuman serve` (issue 18 benchmarks): claims the driver token, sends each
command, then prints per second the real-time factor and the latencies the server measured.
Usage: scripts/web_bench.py http://127.0.0.1:8080 "sit on the sofa" "lie on the bed"
"""
import json, sys, time, urllib.request
base = sys.argv[1]; cmds = sys.argv[2:]
def post(path, body):
    req = urllib.request.Request(base + path, data=json.dumps(body).encode(), method='POST', headers={'Content-Type': 'application/json'})
    try:
        with urllib.request.urlopen(req) as r: return r.status, json.load(r)
    except urllib.error.HTTPError as e: return e.code, json.load(e)
def state():
    with urllib.request.urlopen(base + '/api/state') as r: return json.load(r)
code, j = post('/api/drive', {}); tok = j.get('token')
time.sleep(3)
for cmd in cmds:
    s0 = state(); t0 = time.time()
    print(cmd, post('/api/command', {'token': tok, 'text': cmd})[0])
    rtfs = []
    for i in range(15):
        time.sleep(1); post('/api/drive', {'token': tok})
        s = state(); rtfs.append(s['real_time_factor'])
    print('  latency first frame %.0f ms, first motion (pelvis 5 cm) %.0f ms; state %s; rtf per second %s; sim %.1f s in %.1f s wall' % (
        s['latency_first_frame_ms'], s['latency_first_motion_ms'], s['state'], [round(r,2) for r in rtfs], s['sim_time_s']-s0['sim_time_s'], time.time()-t0))
