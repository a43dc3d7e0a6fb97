#!/usr/bin/env python3
"""PeerRoundsTest: rounds of ours against the peer's runs either side of each (tools/shadowbench/peer_rounds.py):
a round's peer time is the mean of its neighbours, the ratio the median over rounds, and runs that do not bracket
the rounds are refused."""
import pathlib
import sys

TOOL = pathlib.Path(sys.argv[1])
sys.path.insert(0, str(TOOL.parent))
from peer_rounds import bracketed, median_ratio  # noqa: E402


def run(shadowed, unshadowed=1.0):
    return {"shadowedMs": {"median": shadowed}, "unshadowedMs": {"median": unshadowed}}


failures = []
# The machine slows from 10 to 30 ms a peer frame over three rounds; ours runs at 0.5x the peer throughout.
peers = [run(10.0), run(14.0), run(22.0), run(30.0)]
vdsm = bracketed(peers, "shadowedMs", 3)
if vdsm != [12.0, 18.0, 26.0]:
    failures.append(f"each round against the mean of the runs either side: expected [12, 18, 26], got {vdsm}")
ratio = median_ratio([6.0, 9.0, 13.0], vdsm)
if abs(ratio - 0.5) > 1e-12:
    failures.append(f"a steady 0.5x through the drift: got {ratio}")
# One round of ours slowed tenfold (a stall) moves the median no further than its rank.
if abs(median_ratio([6.0, 9.0, 130.0], vdsm) - 0.5) > 1e-12:
    failures.append("one outlying round moves the median no more than its rank")
if bracketed([run(1.0, 4.0), run(1.0, 6.0)], "unshadowedMs", 1) != [5.0]:
    failures.append("the unshadowed pass is bracketed the same way")
for bad in (lambda: bracketed(peers[:3], "shadowedMs", 3), lambda: median_ratio([1.0], [1.0, 2.0]),
            lambda: median_ratio([], [])):
    try:
        bad()
        failures.append("rounds the peer's runs do not bracket are refused")
    except ValueError:
        pass

for failure in failures:
    print("FAIL:", failure)
print(f"{5 - len(failures)} of 5 cases pass")
sys.exit(1 if failures else 0)
