#!/usr/bin/env python3
"""peak_memory.py LIMIT_MB COMMAND...: runs COMMAND, which must exit 0, and fails if its peak
resident memory (the largest of the process's resident set, as the kernel reports it to the
parent) passes LIMIT_MB megabytes (10^6 bytes). Prints the peak."""
import resource
import subprocess
import sys

limit_mb = float(sys.argv[1])
result = subprocess.run(sys.argv[2:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024 / 1e6
print(f"peak_memory: exit {result.returncode}, peak resident memory {peak_mb:.0f} MB (limit {limit_mb:.0f} MB)")
if result.returncode != 0:
    sys.stderr.write(result.stderr)
    sys.exit(1)
if result.stderr:
    sys.stderr.write("peak_memory: stderr is not empty:\n" + result.stderr)
    sys.exit(1)
sys.exit(0 if peak_mb <= limit_mb else 1)
