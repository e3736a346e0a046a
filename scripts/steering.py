#!/usr/bin/env python3
"""Does a river creature steer? Its travel against the resource's bearing and its start heading.

    scripts/steering.py REPLAY...

Each REPLAY is a river evaluation's replay (`bestiary simulate F.json --seed S
--replay R.json`), one per seed, under a random start heading
(`--set task.start_yaw_jitter=180`). From each: the torso's start heading (its
first pose's turn about the vertical), the bearing from its start to the
resource's cell (the replay's grid), and its direction of travel (start to
end). Over the replays, the resultant length (0 to 1) of two angles:
- travel minus the resource's bearing: 1 when it goes the resource's way
  whatever way it faced (it steers);
- travel minus its start heading: 1 when it goes the same way relative to its
  body every time (an open loop, which its start heading aims).
Prints both and the mean travel (m); docs/rivercrossing.md says what they
showed. Standard library only.
"""
import json
import math
import sys


def angles(path):
    """(travel - bearing, travel - start heading, travel in m) of one replay."""
    with open(path) as f:
        r = json.load(f)
    frames = r["frames"]
    grids = [e["grid"] for e in r["scene"]["record"]["events"] if "grid" in e]
    if not grids:
        raise ValueError(path + ": no grid in its scene record (not a river replay)")
    g = grids[0]
    kinds = [k["name"] for k in r["scene"]["record"]["cell_kinds"]]
    resource = kinds.index("resource")
    cells = [i for i, c in enumerate(g["cells"]) if c == resource]
    if not cells:
        raise ValueError(path + ": no resource cell in its grid")
    w, size = g["width"], g["cell"]
    rx = g["origin"][0] + (cells[0] % w + 0.5) * size
    ry = g["origin"][1] + (cells[0] // w + 0.5) * size
    pose = frames[0]["poses"][0]  # x, y, z, then the quaternion w, x, y, z
    heading = 2 * math.atan2(pose[6], pose[3])
    a, b = frames[0]["com"], frames[-1]["com"]
    bearing = math.atan2(ry - a[1], rx - a[0])
    travel = math.atan2(b[1] - a[1], b[0] - a[0])
    return travel - bearing, travel - heading, math.hypot(b[0] - a[0], b[1] - a[1])


def resultant(xs):
    """The length of the mean unit vector of angles xs: 1 when all agree, near 0 when spread."""
    return math.hypot(sum(math.cos(x) for x in xs), sum(math.sin(x) for x in xs)) / len(xs)


def main(argv):
    if len(argv) < 2:
        print("usage: steering.py REPLAY... (river replays under random start headings)", file=sys.stderr)
        return 2
    try:
        a = [angles(p) for p in argv[1:]]
    except (OSError, ValueError, KeyError, IndexError) as e:
        print("steering.py: " + str(e), file=sys.stderr)
        return 2
    print("replays %d  toward the resource %.2f  along the start heading %.2f  travel %.2f m" %
          (len(a), resultant([x[0] for x in a]), resultant([x[1] for x in a]), sum(x[2] for x in a) / len(a)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
