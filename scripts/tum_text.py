"""TUM trajectory files (timestamp tx ty tz qx qy qz qw) as the measurement scripts read them."""


def read_tum_xy(path):
    """The file's stamps (s) and (x, y) positions, in file order; comments and blank lines
    skipped."""
    stamps, xy = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            p = line.split()
            stamps.append(float(p[0]))
            xy.append((float(p[1]), float(p[2])))
    return stamps, xy
