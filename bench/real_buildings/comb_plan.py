"""A comb-shaped building for import benchmarks: one main corridor along x, branch corridors
along y every 12 m, and rooms every 4 m on both sides of each branch, PER_BRANCH rooms a branch
(default 100: branches 200 m long; ROOMS: one branch, a single corridor ROOMS x 2 m long), as OSM
Simple Indoor Tagging GeoJSON near lon/lat (0, 0) (1 m = 1/111320 degree). With GAP_M, rooms are
drawn that far apart from each other and from the corridor (the walls left out, as OSM drawings
often do); with 0, they touch.

    comb_plan.py ROOMS OUT.geojson [GAP_M [PER_BRANCH]]
"""
import json
import math
import sys

rooms, out = int(sys.argv[1]), sys.argv[2]
h = float(sys.argv[3]) / 2 if len(sys.argv) > 3 else 0.0
per_branch = int(sys.argv[4]) if len(sys.argv) > 4 else 100
deg = 1 / 111320.0
branches = max(1, math.ceil(rooms / per_branch))
side = math.ceil(per_branch / 2)  # rooms a side of a branch
features = []


def poly(x0, y0, x1, y1, indoor):
    ring = [[x0 * deg, y0 * deg], [x1 * deg, y0 * deg], [x1 * deg, y1 * deg],
            [x0 * deg, y1 * deg], [x0 * deg, y0 * deg]]
    features.append({"type": "Feature",
                     "properties": {"@id": f"way/{len(features) + 1}", "indoor": indoor,
                                    "level": "1"},
                     "geometry": {"type": "Polygon", "coordinates": [ring]}})


poly(0, 0, branches * 12.0, 2.5, "corridor")
made = 0
for b in range(branches):
    x = b * 12.0 + 4.0
    poly(x, 2.5, x + 2.0, 2.5 + 4.0 * side, "corridor")
    for j in range(side):
        for left in (True, False):
            if made == rooms:
                break
            y = 2.5 + 4.0 * j
            if left:
                poly(x - 4.0 + h, y + h, x - h, y + 4.0 - h, "room")
            else:
                poly(x + 2.0 + h, y + h, x + 6.0 - h, y + 4.0 - h, "room")
            made += 1
json.dump({"type": "FeatureCollection", "features": features}, open(out, "w"))
