"""The lab under a class: tables built at start, the first Apply, and 30 students at once on loopback.

    python benchmarks/bench_lab.py [--students 30] [--rounds 6] [--class rig/lab/examples/class.toml]

Starts ``rig lab``'s server in this process (werkzeug, threaded, 127.0.0.1, any free port) with the
class file, runs the start-up preparation (Lab.prepare: every exercise's contact tables) and prints
how long it took, then the first Apply (POST controls) of a fresh session of each exercise, then
``--students`` threads, each a student who joins with the class's code, opens exercise A1 and
repeats ``--rounds`` times: Apply, Record, then the requests that simulate nothing (GET state,
Check, nu lookup, readings.csv, GET me). It prints the median and 95th percentile of those
non-simulation requests and of the simulation ones (Apply, Record), and the wall time. Bounded:
30 students x 6 rounds is about 1 000 requests.
"""

from __future__ import annotations

import argparse
import json
import logging
import statistics
import tempfile
import threading
import time
import urllib.error
import urllib.request
from pathlib import Path

from werkzeug.serving import make_server

from rig.lab.app import Lab, create_app
from rig.lab.exercises import ClassFile

EXAMPLE = Path(__file__).resolve().parents[1] / "rig" / "lab" / "examples" / "class.toml"


def call(base: str, method: str, path: str, body=None, token=None, timeout=300.0):
    """(status, seconds, parsed answer) of one request."""
    data = None if body is None else json.dumps(body).encode()
    headers = {"Content-Type": "application/json"} | ({"X-Lab-Token": token} if token else {})
    req = urllib.request.Request(base + path, data=data, method=method, headers=headers)
    start = time.perf_counter()
    try:
        with urllib.request.urlopen(req, timeout=timeout) as response:
            status, text, kind = response.status, response.read(), response.headers.get_content_type()
    except urllib.error.HTTPError as error:
        status, text, kind = error.code, error.read(), error.headers.get_content_type()
    seconds = time.perf_counter() - start
    return status, seconds, json.loads(text) if kind == "application/json" else text


def student(base: str, code: str, name: str, rounds: int, quick: list, slow: list, errors: list) -> None:
    status, _, answer = call(base, "POST", "/api/join", {"student": name, "join_code": code})
    if status != 201:
        errors.append((name, "join", status, answer))
        return
    token = answer["token"]
    status, _, state = call(base, "POST", "/api/sessions", {"stand": "yoke", "exercise": "A1"}, token)
    if status != 201:
        errors.append((name, "open", status, state))
        return
    sid = f"/api/sessions/{state['id']}"
    for k in range(rounds):
        for method, path, body, bucket in (
                ("POST", f"{sid}/controls", {"settings": {"brake_setpoint_N_m": 0.3 + 0.1 * k}}, slow),
                ("POST", f"{sid}/record", {"gate_time_s": 1.0}, slow),
                ("GET", sid, None, quick),
                ("POST", f"{sid}/nu", {"point": k, "l_over_a": 0.3, "c_over_a": 0.0, "alpha_prime": 0.6}, quick),
                ("GET", f"{sid}/readings.csv", None, quick),
                ("GET", "/api/me", None, quick),
                ("POST", f"{sid}/check", {"point": k, "answers": {"l_over_a": 0.3, "c_over_a": 0.0, "mu_v": 0.4,
                                                                  "mu_T": 0.4}}, quick)):
            status, seconds, answer = call(base, method, path, body, token)
            if status >= 500 or (status >= 400 and not path.endswith("/check")):
                errors.append((name, path, status, answer))
            bucket.append(seconds)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=30)
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--class", dest="classfile", type=Path, default=EXAMPLE)
    args = parser.parse_args()
    logging.getLogger("werkzeug").setLevel(logging.WARNING)  # no line per request
    classfile = ClassFile.load(args.classfile)
    with tempfile.TemporaryDirectory(prefix="bench-lab-") as folder:
        lab = Lab(Path(folder), classfile)
        server = make_server("127.0.0.1", 0, create_app(lab), threaded=True)
        base = f"http://127.0.0.1:{server.server_port}"
        threading.Thread(target=server.serve_forever, daemon=True).start()
        start = time.perf_counter()
        lab.prepare(lambda line: print(f"  {line}", flush=True))
        print(f"start-up preparation (every exercise's tables): {time.perf_counter() - start:.1f} s")
        listed = classfile.students[0]
        token = lab.roster.token_of(listed)
        for exercise in classfile.exercises.values():
            status, _, state = call(base, "POST", "/api/sessions", {"stand": exercise.stand, "exercise": exercise.id},
                                    token)
            status, seconds, _ = call(base, "POST", f"/api/sessions/{state['id']}/controls", {"settings": {}}, token)
            print(f"first Apply, exercise {exercise.id} ({exercise.stand}): {seconds:.2f} s (HTTP {status})")
        quick, slow, errors = [], [], []
        threads = [threading.Thread(target=student, args=(base, classfile.join_code, f"bench-{k}", args.rounds,
                                                          quick, slow, errors)) for k in range(args.students)]
        start = time.perf_counter()
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        wall = time.perf_counter() - start
        server.shutdown()

    def quantiles(values):
        ordered = sorted(values)
        return statistics.median(ordered) * 1e3, ordered[int(0.95 * (len(ordered) - 1))] * 1e3

    print(f"{args.students} students x {args.rounds} rounds on loopback: {len(quick) + len(slow)} requests in "
          f"{wall:.1f} s, {len(errors)} errors")
    print("non-simulation requests (state, Check, nu lookup, readings.csv, me): median %.0f ms, 95 %% %.0f ms (n = %d)"
          % (*quantiles(quick), len(quick)))
    print("simulation requests (Apply, Record): median %.0f ms, 95 %% %.0f ms (n = %d)" % (*quantiles(slow), len(slow)))
    for error in errors[:5]:
        print("error:", error)


if __name__ == "__main__":
    main()
