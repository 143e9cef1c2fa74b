#!/usr/bin/env python3
# A faithful port of the TUM RGB-D benchmark's evaluate_ate.py (Juergen Sturm, TUM, BSD licence)
# to Python 3 / current numpy: the same file reading (read_file_list of associate.py), the same
# greedy timestamp association, the same Horn alignment (SVD with the reflection fix, no scale)
# and the same RMSE. Used by tests/eval to cross-check the C++ evaluation on identical files.
#
#   evaluate_ate.py groundtruth.txt estimate.txt [--max_difference 0.02] [--offset 0]
# prints the ATE RMSE (metres) with 17 significant digits.
import argparse
import sys

import numpy


def read_file_list(filename):
    """associate.py: 'stamp d1 d2 ...' per line, ',' or tab also separate, '#' comments."""
    with open(filename) as f:
        data = f.read()
    lines = data.replace(",", " ").replace("\t", " ").split("\n")
    rows = [[v.strip() for v in line.split(" ") if v.strip() != ""]
            for line in lines if len(line) > 0 and line[0] != "#"]
    rows = [(float(l[0]), l[1:]) for l in rows if len(l) > 1]
    return dict(rows)


def associate(first_list, second_list, offset, max_difference):
    """associate.py: greedy by smallest |dt| below max_difference, each stamp used once."""
    first_keys = list(first_list.keys())
    second_keys = list(second_list.keys())
    potential_matches = [(abs(a - (b + offset)), a, b)
                         for a in first_keys
                         for b in second_keys
                         if abs(a - (b + offset)) < max_difference]
    potential_matches.sort()
    matches = []
    for diff, a, b in potential_matches:
        if a in first_keys and b in second_keys:
            first_keys.remove(a)
            second_keys.remove(b)
            matches.append((a, b))
    matches.sort()
    return matches


def align(model, data):
    """evaluate_ate.py: Horn's method; model, data are 3xn; returns rot, trans, trans_error."""
    model_zerocentered = model - model.mean(1, keepdims=True)
    data_zerocentered = data - data.mean(1, keepdims=True)
    W = numpy.zeros((3, 3))
    for column in range(model.shape[1]):
        W += numpy.outer(model_zerocentered[:, column], data_zerocentered[:, column])
    U, d, Vh = numpy.linalg.svd(W.transpose())
    S = numpy.identity(3)
    if numpy.linalg.det(U) * numpy.linalg.det(Vh) < 0:
        S[2, 2] = -1
    rot = U @ S @ Vh
    trans = data.mean(1, keepdims=True) - rot @ model.mean(1, keepdims=True)
    model_aligned = rot @ model + trans
    alignment_error = model_aligned - data
    trans_error = numpy.sqrt(numpy.sum(alignment_error * alignment_error, 0))
    return rot, trans, trans_error


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("first_file")
    parser.add_argument("second_file")
    parser.add_argument("--offset", type=float, default=0.0)
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--max_difference", type=float, default=0.02)
    args = parser.parse_args()
    first_list = read_file_list(args.first_file)
    second_list = read_file_list(args.second_file)
    matches = associate(first_list, second_list, args.offset, args.max_difference)
    if len(matches) < 2:
        sys.exit("couldn't find matching timestamp pairs")
    first_xyz = numpy.array([[float(v) for v in first_list[a][0:3]] for a, b in matches]).T
    second_xyz = numpy.array(
        [[float(v) * args.scale for v in second_list[b][0:3]] for a, b in matches]).T
    rot, trans, trans_error = align(second_xyz, first_xyz)
    rmse = numpy.sqrt(numpy.dot(trans_error, trans_error) / len(trans_error))
    print(f"{len(matches)} {rmse:.17g}")


if __name__ == "__main__":
    main()
