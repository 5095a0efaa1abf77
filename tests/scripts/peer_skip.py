"""What a Python-driven test does when a peer it needs is missing (the Python twin of
tests/peer_skip.hpp): normally skipped, saying why, with exit 77 (ctest SKIP_RETURN_CODE);
where every peer is installed (CI), a failure instead: CPKIT_REQUIRE_PEERS=1, or CI=true unless
CPKIT_REQUIRE_PEERS=0."""
import os
import sys

REQUIRED_BY = "(a missing peer fails where peers are required: CI=true or CPKIT_REQUIRE_PEERS=1)"


def peers_required():
    """True where a missing peer fails the test rather than skipping it."""
    r = os.environ.get("CPKIT_REQUIRE_PEERS", "")
    if r:
        return r == "1"
    return os.environ.get("CI", "") in ("true", "1")


def skip(reason):
    """Ends the program: exit 77 (ctest: skipped), or exit 1 where peers are required."""
    reason = reason.strip()
    if peers_required():
        print(f"FAILED: {reason} {REQUIRED_BY}", flush=True)
        sys.exit(1)
    print(f"skipped: {reason}", flush=True)
    sys.exit(77)
