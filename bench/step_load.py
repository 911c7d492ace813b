#!/usr/bin/env python3
"""A load test of the step service (scripts/step-server) on this machine: students posting steps
at once, and a long solution in flight while another student posts one step.

Every request goes to 127.0.0.1, to a server this script starts and stops itself; the number of
requests is bounded (at most 500 students of at most 10 steps in one round) and so is the time
(each request 30 s at most, each round --max-seconds, 60 by default).

1. For each count of students (10, 50 and 200 by default), all start together; each posts its
   steps one after the other, each on a connection of its own as the page's fetch() does: an
   equation right, an equation wrong, an answer right, an answer wrong (sample 12.3, each
   student's own coefficients, so no two students send the same text). Printed: the latency
   of each request (p50, p99, max), the errors (a refused or dropped connection, a status that
   is not 200, a verdict that is not the one by hand), and the round's wall time.
2. The delay: one student's step alone (the median of 11), then the same step posted while a
   solution of --solution-steps distinct equations is being checked (posted 5 ms after the
   whole solution was sent; each of 5 rounds); the delay is the step's latency then less its
   latency alone, and whether the solution was still being checked when the step was answered
   is counted.

Usage: bench/step_load.py [--build DIR] [--workers N] [--students 10,50,200] [--steps 4]
                          [--solution-steps 200] [--server SCRIPT] [--max-seconds 60]
--server runs another server script (an older scripts/step-server, to compare) with the same
arguments but --workers."""
import argparse
import asyncio
import json
import os
import statistics
import subprocess
import sys
import threading
import time
import urllib.parse

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROBLEM = os.path.join(ROOT, "examples", "sample-12.3-two-mass-pulley.yaml")
HOST = "127.0.0.1"  # the only host this script sends to
MAX_STUDENTS, MAX_STEPS, REQUEST_TIMEOUT = 500, 10, 30.0


def student_steps(k, count):
    """Student k's steps (sample 12.3 by hand: 2T - F = m_A a_A, T = 20 N at the description's
    numbers; B's balance with two strands of three is wrong, 30 N too), and their verdicts."""
    c = k + 2
    steps = [({"kind": "equation", "equation": "%d*T - %d*F = %d*m_A*ddot(x_A)" % (2 * c, c, c)}, "correct"),
             ({"kind": "equation", "equation": "-%d*T = %d*m_B*ddot(x_B)" % (2 * c, c)}, "incorrect"),
             ({"kind": "answer", "unknown": "T", "answer": "%d*F*m_B/(%d*m_A + %d*m_B)" % (2 * c, 9 * c, 4 * c)}, "correct"),
             ({"kind": "answer", "unknown": "T", "answer": "%d N" % (30 + k % 7)}, "incorrect")]
    return (steps * (count // 4 + 1))[:count]


def long_solution(n):
    """n distinct equations: LMB A and LMB B scaled, every third one with a strand missing."""
    steps = []
    for k in range(n):
        c = k + 2
        if k % 3 == 2:
            steps.append({"equation": "-%d*T = %d*m_B*ddot(x_B)" % (2 * c, c)})
        elif k % 2:
            steps.append({"equation": "-%d*T = %d*m_B*ddot(x_B)" % (3 * c, c)})
        else:
            steps.append({"equation": "%d*T - %d*F = %d*m_A*ddot(x_A)" % (2 * c, c, c)})
    return {"steps": steps}


async def post(port, path, obj, sent=None):
    """(seconds, status, parsed body or None, error text or None); `sent` is set once the
    request is written."""
    body = json.dumps(obj).encode()
    start = time.perf_counter()
    try:
        reader, writer = await asyncio.wait_for(asyncio.open_connection(HOST, port), REQUEST_TIMEOUT)
        writer.write(b"POST %s HTTP/1.1\r\nHost: %s:%d\r\nContent-Type: application/json\r\nContent-Length: %d\r\n"
                     b"Connection: close\r\n\r\n" % (path.encode(), HOST.encode(), port, len(body)) + body)
        await writer.drain()
        if sent:
            sent.set()
        data = await asyncio.wait_for(reader.read(), REQUEST_TIMEOUT)
        writer.close()
    except (OSError, asyncio.TimeoutError) as e:
        return time.perf_counter() - start, None, None, "%s: %s" % (type(e).__name__, e)
    elapsed = time.perf_counter() - start
    head, _, payload = data.partition(b"\r\n\r\n")
    try:
        status = int(head.split(b" ", 2)[1])
        return elapsed, status, json.loads(payload), None
    except (IndexError, ValueError):
        return elapsed, None, None, "unreadable answer: %r" % data[:80]


async def students_round(port, n, steps):
    start = asyncio.Event()
    latencies, errors = [], []

    async def student(k):
        await start.wait()
        for step, verdict in student_steps(k, steps):
            elapsed, status, r, error = await post(port, "/step", step)
            latencies.append(elapsed)
            if error or status != 200:
                errors.append(error or "status %s" % status)
            elif r.get("verdict") != verdict:
                errors.append("verdict %s for %s (by hand: %s)" % (r.get("verdict"), step, verdict))

    tasks = [asyncio.create_task(student(k)) for k in range(n)]
    await asyncio.sleep(0.05)
    t0 = time.perf_counter()
    start.set()
    await asyncio.gather(*tasks)
    return latencies, errors, time.perf_counter() - t0


async def delay_round(port, solution_steps, rounds=5):
    step = ({"kind": "equation", "equation": "2*T - F = m_A*ddot(x_A)"}, "correct")
    alone = []
    for _ in range(11):
        elapsed, status, r, error = await post(port, "/step", step[0])
        assert status == 200 and r["verdict"] == "correct", (status, r, error)
        alone.append(elapsed)
    solution = long_solution(solution_steps)
    # The solution alone, for scale.
    solution_alone, status, g, error = await post(port, "/solution", solution)
    assert status == 200 and len(g.get("steps", [])) == solution_steps, (status, error, str(g)[:300])
    results = []
    for _ in range(rounds):
        sent = asyncio.Event()
        long_task = asyncio.create_task(post(port, "/solution", solution, sent))
        await sent.wait()  # the whole solution written to the server
        await asyncio.sleep(0.005)  # (a worker has taken it)
        elapsed, status, r, error = await post(port, "/step", step[0])
        solution_in_flight = not long_task.done()
        solution_elapsed, s_status, g, s_error = await long_task
        assert status == 200 and r["verdict"] == "correct", (status, r, error)
        assert s_status == 200, (s_status, s_error)
        results.append((elapsed, solution_elapsed, solution_in_flight))
    return statistics.median(alone), solution_alone, results


def percentile(values, p):
    values = sorted(values)
    return values[min(len(values) - 1, max(0, int(round(p / 100 * len(values) + 0.5)) - 1))]


def start_server(args):
    script = args.server or os.path.join(ROOT, "scripts", "step-server")
    cmd = [sys.executable, script, PROBLEM, "--port", "0", "--build", args.build, "--quiet"]
    if not args.server:
        cmd += ["--workers", str(args.workers)]
    process = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    url = process.stdout.readline().strip()
    if not url:
        raise SystemExit("the server did not start: " + process.stderr.read())
    parsed = urllib.parse.urlparse(url)
    assert parsed.hostname == HOST, url
    threading.Thread(target=process.stderr.read, daemon=True).start()
    time.sleep(1.0)  # the workers load the problem
    return process, parsed.port


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--workers", type=int, default=0, help="the server's --workers (0: one a core)")
    ap.add_argument("--students", default="10,50,200")
    ap.add_argument("--steps", type=int, default=4, help="steps each student posts")
    ap.add_argument("--solution-steps", type=int, default=200, help="the long solution's steps (tackle takes at most 200)")
    ap.add_argument("--server", help="another server script to run (no --workers given to it)")
    ap.add_argument("--max-seconds", type=float, default=60.0, help="the longest one round may take")
    args = ap.parse_args()
    counts = [int(x) for x in args.students.split(",")]
    if any(not 1 <= n <= MAX_STUDENTS for n in counts) or not 1 <= args.steps <= MAX_STEPS:
        ap.error("students from 1 to %d, steps from 1 to %d" % (MAX_STUDENTS, MAX_STEPS))
    process, port = start_server(args)
    try:
        load = os.getloadavg()
        print("server: %s, %s worker(s); %d cores; load average before: %.2f %.2f %.2f"
              % (args.server or "scripts/step-server", args.workers or "one a core", os.cpu_count(), *load))
        print("\n| students at once | requests | p50 | p99 | max | errors | wall time |")
        print("|---|---|---|---|---|---|---|")
        for n in counts:
            latencies, errors, wall = asyncio.run(asyncio.wait_for(students_round(port, n, args.steps), args.max_seconds))
            print("| %d | %d | %.0f ms | %.0f ms | %.0f ms | %d | %.2f s |"
                  % (n, len(latencies), percentile(latencies, 50) * 1000, percentile(latencies, 99) * 1000,
                     max(latencies) * 1000, len(errors), wall), flush=True)
            for e in sorted(set(errors))[:5]:
                print("  error:", e)
        alone, solution_alone, rounds = asyncio.run(asyncio.wait_for(delay_round(port, args.solution_steps), args.max_seconds))
        print("\none step alone: %.1f ms (median of 11); the solution of %d steps alone: %.0f ms"
              % (alone * 1000, args.solution_steps, solution_alone * 1000))
        print("the step posted 5 ms after the solution was sent, 5 rounds: latency %s ms; delay (less alone) max %.0f ms;"
              " the solution took %s ms; still in flight when the step was answered: %d of 5"
              % (", ".join("%.0f" % (e * 1000) for e, _, _ in rounds), max(e - alone for e, _, _ in rounds) * 1000,
                 ", ".join("%.0f" % (s * 1000) for _, s, _ in rounds), sum(f for _, _, f in rounds)))
    finally:
        process.terminate()
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            process.kill()
    return 0


if __name__ == "__main__":
    sys.exit(main())
