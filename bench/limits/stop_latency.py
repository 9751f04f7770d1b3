#!/usr/bin/env python3
"""How quickly `hlr draw` stops on SIGINT (issue 17: within a second on a 1M-face run).

Starts `hlr draw MESH --view VIEW --threads T -o OUT.json --progress`, sends SIGINT after each
delay, and reports per run: the stage the progress line showed last, the seconds from the signal
to the process's exit, its exit code (130 expected) and whether any file was left in the output
folder (none expected: neither the output nor its temporary file).

usage: bench/limits/stop_latency.py HLR MESH [--view iso] [--threads 2] [--delays 2,5,10,20,40]
                                   [--after-stage TEXT]
With --after-stage, each delay counts from the first progress line containing TEXT (such as
"classifying"), so that a loaded machine, which reaches each stage later, still stops the stage
meant. Prints one CSV row per delay: delay,stage,latency_seconds,exit_code,files_left
"""
import argparse
import os
import signal
import subprocess
import tempfile
import threading
import time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("hlr")
    ap.add_argument("mesh")
    ap.add_argument("--view", default="iso")
    ap.add_argument("--threads", default="2")
    ap.add_argument("--delays", default="2,5,10,20,40")
    ap.add_argument("--after-stage", default="")
    args = ap.parse_args()
    print("delay,stage,latency_seconds,exit_code,files_left")
    for delay in (float(d) for d in args.delays.split(",")):
        with tempfile.TemporaryDirectory() as out_dir:
            proc = subprocess.Popen(
                [args.hlr, "draw", args.mesh, "--view", args.view, "--threads", args.threads,
                 "-o", os.path.join(out_dir, "out.json"), "--progress"],
                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            last = [""]
            reached = threading.Event()
            if not args.after_stage:
                reached.set()

            def read_progress():
                for line in proc.stderr:
                    last[0] = line.strip()
                    if args.after_stage and args.after_stage in line:
                        reached.set()
                reached.set()  # the run ended first

            reader = threading.Thread(target=read_progress)
            reader.start()
            reached.wait()
            time.sleep(delay)
            stage = last[0].replace(",", ";")
            sent = time.monotonic()
            if proc.poll() is None:
                proc.send_signal(signal.SIGINT)
            code = proc.wait()
            latency = time.monotonic() - sent
            reader.join()
            left = len(os.listdir(out_dir))
            print(f"{delay:g},{stage},{latency:.3f},{code},{left}", flush=True)


if __name__ == "__main__":
    main()
