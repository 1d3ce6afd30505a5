#!/usr/bin/env python3
"""Load figure of the DNC link (issue 13 item 6, short form): N pymodbus clients poll the
status block (input registers 0..33) at RATE Hz each for SECONDS against a running
`trilho-cli serve` on 127.0.0.1:PORT. Prints requests, errors, late (> 50 ms) and latency
percentiles. Usage: dnc_load.py PORT [N=20] [RATE=100] [SECONDS=10]"""
import sys
import threading
import time

from pymodbus.client import ModbusTcpClient

port = int(sys.argv[1])
n = int(sys.argv[2]) if len(sys.argv) > 2 else 20
rate = float(sys.argv[3]) if len(sys.argv) > 3 else 100.0
seconds = float(sys.argv[4]) if len(sys.argv) > 4 else 10.0
lat, errors, lock = [], [0], threading.Lock()


def client():
    c = ModbusTcpClient("127.0.0.1", port=port, timeout=2)
    c.connect()
    mine, bad = [], 0
    t0 = time.monotonic()
    k = 0
    while True:
        due = t0 + k / rate
        if due - t0 >= seconds:
            break
        now = time.monotonic()
        if due > now:
            time.sleep(due - now)  # pacing of the poll, not a synchronisation
        s = time.monotonic()
        r = c.read_input_registers(0, 34, slave=1)
        mine.append(time.monotonic() - s)
        if r.isError():
            bad += 1
        k += 1
    c.close()
    with lock:
        lat.extend(mine)
        errors[0] += bad


threads = [threading.Thread(target=client) for _ in range(n)]
start = time.monotonic()
for t in threads:
    t.start()
for t in threads:
    t.join()
elapsed = time.monotonic() - start
lat.sort()
p = lambda q: lat[min(len(lat) - 1, int(q * len(lat)))] * 1e3
print(f"{n} clients x {rate:g} Hz x {seconds:g} s: {len(lat)} requests "
      f"({len(lat) / elapsed:.0f}/s), {errors[0]} errors, {sum(1 for x in lat if x > 0.05)} over 50 ms; "
      f"latency p50 {p(0.5):.2f} ms, p99 {p(0.99):.2f} ms, max {lat[-1] * 1e3:.2f} ms")
