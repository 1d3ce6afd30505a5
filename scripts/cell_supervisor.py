#!/usr/bin/env python3
"""The cell's supervisor (issue 13 item 7), as the seed's cell would have one: over Modbus TCP
(pymodbus) it downloads a program to each machine of the cell, starts them all, and prints
their state side by side every REFRESH seconds until every one has finished, then checks that
each ended where its program ends. Started by scripts/cell-demo, which starts the machines.

Usage: cell_supervisor.py PORT [PORT...] [--timeout S=120] [--refresh S=0.5]
Machine i (1-based, in the order of the ports) gets program 100+i: out to 100+40*i mm at F60
(feeds are % of the rail's top speed), a 0.5 s dwell, back to -20*i mm at F100, m02 (so at
most 20 machines: their targets must fit the rail's +-850 mm).
Exit 0 when all finished on their targets, 1 otherwise, 77 when pymodbus is missing."""
import argparse
import struct
import sys
import time

try:
    from pymodbus.client import ModbusTcpClient
except ImportError:
    print("cell_supervisor: python3-pymodbus is not installed: skipped")
    sys.exit(77)

# core/dnc/register_map.h (PDU addresses) and docs/dnc.md
IN_STATE, IN_BLOCK_N, IN_PROGRAM, IN_FINISHED, IN_ALARMS, IN_LAST_ALARM = 2, 6, 8, 9, 10, 14
IN_CMD_SEQ, IN_CMD_RESULT, IN_DIAG_ERRORS, IN_POSITION, IN_COUNT = 16, 17, 19, 24, 34
H_COMMAND, H_DL_NUMBER, H_DL_DATA = 8, 16, 18
START, COMMIT = 1, 8
APPLIED = 1
STATES = ["Manual", "AutoIdle", "Homing", "Running", "Waiting", "Paused", "Alarm", "EStop"]
AUTO_IDLE, ALARM, ESTOP = 1, 6, 7
RESULTS = ["none", "applied", "no such program", "compile errors", "busy", "save failed",
           "bad download block", "not ready", "nothing to do"]
TOLERANCE_MM = 0.5  # the rail's in-position band is tighter; this only tells a wrong target


def program_for(i):
    """Machine i's program and the position (mm) it ends at."""
    out, back = 100 + 40 * i, -20 * i
    text = (f"( cell demo: machine {i} )\n"
            f"N0010 G90\n"
            f"N0020 G01 X{out} F60\n"
            f"N0030 G04 X0.5\n"
            f"N0040 G01 X{back} F100\n"
            f"N0050 M02\n")
    return 100 + i, text, float(back)


def f32(hi, lo):
    return struct.unpack(">f", struct.pack(">HH", hi, lo))[0]


class Machine:
    def __init__(self, index, port):
        self.index, self.port = index, port
        self.number, self.text, self.target = program_for(index)
        self.c = ModbusTcpClient("127.0.0.1", port=port, timeout=5)
        if not self.c.connect():
            raise SystemExit(f"cell_supervisor: machine {index}: cannot connect to 127.0.0.1:{port}")
        self.seq = 0
        self.status = [0] * IN_COUNT

    def read(self):
        r = self.c.read_input_registers(0, IN_COUNT, slave=1)
        if r.isError():
            raise SystemExit(f"cell_supervisor: machine {self.index}: read failed: {r}")
        self.status = r.registers
        return self.status

    def send(self, code, arg):
        """Writes command, argument and seq in one request; returns the seq to wait for."""
        self.seq = (self.seq + 1) % 65536 or 1
        r = self.c.write_registers(H_COMMAND, [code, arg, self.seq], slave=1)
        if r.isError():
            raise SystemExit(f"cell_supervisor: machine {self.index}: command {code} refused: {r}")
        return self.seq

    def result_of(self, seq, seconds=30.0):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            s = self.read()
            if s[IN_CMD_SEQ] == seq:
                return s[IN_CMD_RESULT]
            time.sleep(0.01)  # polling interval of the echo, not a synchronisation
        return -1

    def download(self):
        """The documented block: holding 16 = number, 17 = length, text from 18, command 8."""
        data = self.text.encode("ascii")
        padded = data + (b"\0" if len(data) % 2 else b"")
        words = [(padded[k] << 8) | padded[k + 1] for k in range(0, len(padded), 2)]
        if self.c.write_registers(H_DL_NUMBER, [self.number, len(data)], slave=1).isError():
            raise SystemExit(f"cell_supervisor: machine {self.index}: download header refused")
        for k in range(0, len(words), 120):  # at most 123 registers a request
            if self.c.write_registers(H_DL_DATA + k, words[k:k + 120], slave=1).isError():
                raise SystemExit(f"cell_supervisor: machine {self.index}: download block refused")
        return self.result_of(self.send(COMMIT, self.number))

    def row(self):
        s = self.status
        block = s[IN_BLOCK_N] - 65536 if s[IN_BLOCK_N] >= 32768 else s[IN_BLOCK_N]
        alarms = (s[IN_ALARMS] << 16) | s[IN_ALARMS + 1]
        state = STATES[s[IN_STATE]] if s[IN_STATE] < len(STATES) else str(s[IN_STATE])
        if self.finished():
            state += " (done)"
        return (f"{self.index:>7} {self.port:>6} {state:<16} {s[IN_PROGRAM]:>7} "
                f"{block if block >= 0 else '-':>5} {f32(*s[IN_POSITION:IN_POSITION + 2]):>10.2f} "
                f"{self.target:>8.1f}  "
                + (f"0x{alarms:08x} (last {s[IN_LAST_ALARM]})" if alarms else "-"))

    def finished(self):
        return (self.status[IN_FINISHED] == 1 and self.status[IN_STATE] == AUTO_IDLE
                and self.status[IN_PROGRAM] == self.number)


HEADER = (f"{'machine':>7} {'port':>6} {'state':<16} {'program':>7} {'block':>5} "
          f"{'pos. mm':>10} {'target':>8}  alarms")


def show(machines, elapsed, tty):
    lines = [f"cell of {len(machines)}, {elapsed:5.1f} s", HEADER] + [m.row() for m in machines]
    if tty:
        sys.stdout.write("\x1b[H\x1b[J" + "\n".join(lines) + "\n")  # redraw in place
    else:
        sys.stdout.write("\n".join(lines) + "\n\n")
    sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ports", type=int, nargs="+")
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--refresh", type=float, default=0.5)
    a = ap.parse_args()
    if len(a.ports) > 20:
        raise SystemExit("cell_supervisor: at most 20 machines (their targets must fit the rail)")
    machines = [Machine(i + 1, p) for i, p in enumerate(a.ports)]
    for m in machines:
        r = m.download()
        print(f"machine {m.index} (port {m.port}): program {m.number} downloaded: "
              f"{RESULTS[r] if 0 <= r < len(RESULTS) else r}", flush=True)
        if r != APPLIED:
            if m.read()[IN_DIAG_ERRORS]:
                print(f"  {m.status[IN_DIAG_ERRORS]} compile errors", flush=True)
            return 1
    # Every start is written before any echo is awaited: the machines start together.
    seqs = [m.send(START, m.number) for m in machines]
    for m, seq in zip(machines, seqs):
        r = m.result_of(seq)
        print(f"machine {m.index}: start program {m.number}: "
              f"{RESULTS[r] if 0 <= r < len(RESULTS) else r}", flush=True)
        if r != APPLIED:
            return 1
    tty = sys.stdout.isatty()
    t0 = time.monotonic()
    while True:
        for m in machines:
            m.read()
        elapsed = time.monotonic() - t0
        show(machines, elapsed, tty)
        stuck = [m for m in machines if m.status[IN_STATE] in (ALARM, ESTOP)]
        if stuck or all(m.finished() for m in machines) or elapsed > a.timeout:
            break
        time.sleep(a.refresh)  # the table's refresh period
    failures = 0
    for m in machines:
        pos = f32(*m.status[IN_POSITION:IN_POSITION + 2])
        ok = m.finished() and abs(pos - m.target) <= TOLERANCE_MM
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} machine {m.index} (port {m.port}): program {m.number} "
              f"{'finished' if m.finished() else 'not finished: ' + STATES[m.status[IN_STATE]]} "
              f"at {pos:.3f} mm (target {m.target:.1f} mm)", flush=True)
        m.c.close()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
