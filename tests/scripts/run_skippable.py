"""Runs a program whose exit 77 means "skipped: a peer is missing" (it prints why), e.g.
docs/examples/getfem_punch.py without GetFEM, and passes its exit code on, except that where
peers are required (tests/scripts/peer_skip.py) a 77 becomes a failure.
Usage: python3 run_skippable.py PROGRAM [ARGS...]"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_skip  # noqa: E402

rc = subprocess.run(sys.argv[1:]).returncode
if rc == 77:
    peer_skip.skip(" ".join(os.path.basename(a) for a in sys.argv[1:]) + " exited 77 (why: above)")
sys.exit(rc)
