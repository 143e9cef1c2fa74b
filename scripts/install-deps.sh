#!/usr/bin/env bash
# Installs every Debian 12 package wifislam needs to build, test and benchmark.
# Idempotent: does nothing (and needs no network) when everything is already installed.
# Uses sudo only when not running as root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  mold                                   # the linker (CMakeLists.txt): links in a third of GNU ld's time
  libosmesa6-dev                         # off-screen OpenGL (llvmpipe)
  libembree-dev                          # ray casting for the radio model
  libopencv-dev                          # images, ORB features, RANSAC
  libpng-dev                             # PNG files of datasets (core/png_codec.hpp)
  libeigen3-dev                          # linear algebra, poses
  libcgal-dev libgmp-dev libmpfr-dev     # floor-plan polygon booleans
  libgdal-dev libproj-dev libgeos-dev    # floor-plan import: GeoJSON/OSM reading, projection, buffers
  libexpat1-dev                          # floor-plan import: the .osm pre-check's XML parser
  libceres-dev                           # pose-graph optimisation
  libyaml-cpp-dev nlohmann-json3-dev     # scene files, results
  libcli11-dev libspdlog-dev libfmt-dev  # command line, logging
  libsqlite3-dev sqlite3                 # study results store (and its command-line shell)
  slurm-wlm munge                        # studies on a cluster; the suite starts a one-node one
  libcairo2-dev                          # plots and floor-plan pictures
  libssl-dev                             # SHA-256 for dataset manifests
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy                          # reference port of TUM evaluate_ate.py (eval tests)
  python3-yaml                           # scripts/ap_changes.py (bench/localize)
  python3-opencv                         # systems/opencv_rgbd_odometry (cv2.rgbd), an external system
  librosbag-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev libgeometry-msgs-dev
                                         # export --for rosbag: ROS 1 bags and message types
  python3-rosbag python3-roslz4 python3-genmsg python3-sensor-msgs python3-nav-msgs
  python3-tf2-msgs python3-geometry-msgs
                                         # the tests read the bags back with ROS's own reader
  pybind11-dev python3-dev               # the wifislam Python module (python/)
  python3-pytest python3-matplotlib      # its tests, and the plots of examples/python
)
# --fuzz: also clang, whose compiler-rt has libFuzzer and the sanitizers (scripts/fuzz.sh).
if [ "${1:-}" = "--fuzz" ]; then packages+=(clang); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
