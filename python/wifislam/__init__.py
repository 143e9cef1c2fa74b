"""wifislam for Python: scenes, frames as numpy arrays, Wi-Fi scans, ground truth and scoring.

The package calls the same C++ libraries as the ``wifislam`` command line (through the
pybind11 extension ``wifislam._wifislam``); nothing is implemented twice, so a frame, a dataset
or a metric from Python equals the command's. Long calls (rendering, generating, SLAM,
evaluation) release the GIL.

    import wifislam
    scene = wifislam.Scene.load("scenes/c_hall.yaml")
    for frame in wifislam.Simulator(scene, fps=3, max_frames=10):
        frame.rgb, frame.depth, frame.pose, frame.stamp, frame.scans
    info = wifislam.generate(scene, "/tmp/c_hall", fps=3, max_frames=60)
    run = wifislam.slam(info["dataset"], "/tmp/c_hall_run", wifi=True)
    metrics = wifislam.evaluate(run["run"], info["dataset"])
    wifislam.require(metrics, "ate_rmse_m <= 0.5")

Bad arguments raise the library's errors with the command line's message: ``ParseError`` and
``InvalidInputError`` are ``ValueError``s, ``IoError`` is an ``OSError``,
``RequirementNotMetError`` an ``AssertionError`` (so pytest reports it as a failed check).
docs/python.md is the guide.
"""

from __future__ import annotations

import dataclasses
import json
import math
import numbers
import operator
import os
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _wifislam
from ._arguments import checked
from ._wifislam import (
    ExternalSystemError,
    FacilityError,
    InvalidInputError,
    IoError,
    ParseError,
    RequirementNotMetError,
)

__version__ = _wifislam.__version__

PathLike = Union[str, bytes, "os.PathLike[str]"]

__all__ = [
    "Scene", "Simulator", "Dataset", "Frame", "WifiScan", "WifiReading", "Renderer", "render",
    "camera_pose", "radio_map", "RadioMap", "generate", "slam", "evaluate", "require",
    "read_trajectory", "encode_rgb_png", "encode_depth_png", "channel_of",
    "ParseError", "InvalidInputError", "IoError", "ExternalSystemError",
    "RequirementNotMetError", "FacilityError",
]


Scene = _wifislam.Scene


def _is_path(value: Any) -> bool:
    return isinstance(value, (str, bytes, os.PathLike))


def _path(value: PathLike, what: str) -> str:
    """A path argument as the library takes it: str, bytes or os.PathLike, not empty, with no
    NUL byte (the C++ side would stop at it and read another file, where Python's open()
    refuses), and valid UTF-8, as the command line requires: outputs record paths as UTF-8
    text, and a name in another encoding would fail only after the whole output was written."""
    if not _is_path(value):
        raise TypeError(f"{what}: expected a path (str, bytes or os.PathLike), "
                        f"got {type(value).__name__}")
    text = os.fsdecode(os.fspath(value))
    if not text:
        raise InvalidInputError(f"{what}: the path is empty")
    if "\0" in text:
        raise ValueError(f"{what}: embedded null byte in path {text!r}")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise InvalidInputError(
            f"{what}: {os.fspath(value)!r} is not valid UTF-8 (a file name in another "
            "encoding?): the outputs record paths as UTF-8; rename it") from None
    return text


def _absolute(path: str) -> str:
    """`path` from the current folder, not normalised: os.path.abspath takes "link/.." as text,
    and with a symbolic link `link` that is another folder than the one the system opens."""
    return path if os.path.isabs(path) else os.path.join(os.getcwd(), path)


_load_scene_file = Scene.load


def _scene_load(path: PathLike) -> Scene:
    """A scene file (YAML) loaded and checked; ParseError names the file, line and key."""
    # Absolute at loading, as a Dataset's path: the scene remembers its file, and generate's
    # refusal to replace a folder holding it must find it after a later os.chdir too.
    return _load_scene_file(_absolute(_path(path, "Scene.load")))


Scene.load = staticmethod(_scene_load)


def _scene_from_dict(scene: Mapping[str, Any], source_name: str = "<dict>") -> Scene:
    """A scene from a dict of the scene-file schema (``version: 1`` and the rest).

    The dict is written as JSON (which is YAML) one key per line and loaded by the scene loader
    itself, so every check and default is the file's; errors name ``source_name``, the line of
    that text and the key path.
    """
    if not isinstance(scene, Mapping):
        raise TypeError(f"Scene.from_dict: expected a dict, got {type(scene).__name__}")
    return Scene.from_yaml(json.dumps(scene, indent=2, default=_json_plain), source_name)


def _json_plain(value: Any) -> Any:
    """numpy's scalars and arrays as the Python numbers and lists JSON knows (a seed swept with
    np.arange, a metrics row read back with pandas); anything else is json's TypeError."""
    if isinstance(value, (np.generic, np.ndarray)):
        return value.tolist()
    raise TypeError(f"Object of type {type(value).__name__} is not JSON serializable")


Scene.from_dict = staticmethod(_scene_from_dict)
_scene_from_yaml_text = Scene.from_yaml


def _scene_from_yaml(text: str, source_name: str = "<yaml>") -> Scene:
    """A scene from YAML text of the scene-file schema; errors name ``source_name``."""
    return _scene_from_yaml_text(text, source_name)


# Named as the user calls it, in checked()'s TypeError ("Scene.from_yaml(): text takes ...").
_scene_from_yaml.__qualname__ = "Scene.from_yaml"
Scene.from_yaml = staticmethod(checked(_scene_from_yaml))


def _scene_from_pickle(resolved_yaml: str, source_path: str) -> Scene:
    """What pickle and copy call to rebuild a Scene (Scene.__reduce__): a module-level function,
    so that a pickle names it by reference."""
    return _wifislam._scene_unpickled(resolved_yaml, source_path)


def _scene_reduce(scene: Scene) -> tuple:
    return (_scene_from_pickle, scene._pickle_state())


def _scene_new(cls: type, *args: Any, **kwargs: Any) -> Scene:
    # pybind11's own __new__ gives an instance that holds no scene, and any method of it crashed
    # the interpreter: a Scene is only ever made by the factories (which do not go through
    # __new__) and by unpickling (which calls _scene_from_pickle).
    raise TypeError("wifislam.Scene cannot be created directly: use Scene.load(path), "
                    "Scene.from_dict(d) or Scene.from_yaml(text)")


Scene.__reduce__ = _scene_reduce
Scene.__new__ = staticmethod(_scene_new)


def channel_of(frequency_khz: int) -> int:
    """The IEEE 802.11 channel number of a centre frequency in kHz (2.4 GHz: 2412 MHz is
    channel 1, 2484 MHz channel 14; 5 GHz: 5000 MHz + 5 MHz per channel, 5005 to 5930 MHz;
    6 GHz: 5950 MHz + 5 MHz per channel, 5955 to 7115 MHz, and 5935 MHz channel 2). A channel
    number alone does not say its band: keep the frequency beside it. ValueError for a frequency
    that is no channel's centre in these bands."""
    khz = operator.index(frequency_khz)  # a whole number (TypeError for 2412000.5)
    mhz, rest = divmod(khz, 1000)
    if rest == 0 and mhz == 2484:
        return 14
    if rest == 0 and 2412 <= mhz <= 2472 and (mhz - 2407) % 5 == 0:
        return (mhz - 2407) // 5
    # 5 GHz numbering ends below 5935 MHz, where 6 GHz (802.11ax) starts: 5 GHz channels from
    # 187 up are no Wi-Fi channel in use, and their frequencies are 6 GHz channels 1 to 6.
    if rest == 0 and 5005 <= mhz <= 5930 and mhz % 5 == 0:
        return (mhz - 5000) // 5
    if rest == 0 and mhz == 5935:
        return 2
    if rest == 0 and 5955 <= mhz <= 7115 and mhz % 5 == 0:
        return (mhz - 5950) // 5
    raise ValueError(f"frequency_khz {khz}: not the centre of a 2.4, 5 or 6 GHz Wi-Fi channel")


@dataclasses.dataclass(frozen=True)
class WifiReading:
    """One BSSID heard in a scan (a row of the dataset's wifi.csv)."""

    bssid: str
    rssi_dbm: int
    frequency_khz: int
    ssid: str

    @property
    def channel(self) -> int:
        return channel_of(self.frequency_khz)


@dataclasses.dataclass(frozen=True)
class WifiScan:
    """One sweep over the channels, reported at ``stamp`` (its end)."""

    stamp_ns: int
    start_ns: int
    end_ns: int
    sensor_id: str
    readings: Tuple[WifiReading, ...]

    @property
    def stamp(self) -> float:
        return self.stamp_ns * 1e-9


# eq=False: frames compare (and hash) as objects; a field-wise == of their arrays would raise
# numpy's "truth value of an array is ambiguous".
@dataclasses.dataclass(frozen=True, eq=False)
class Frame:
    """One RGB-D frame in route order.

    rgb:      H x W x 3 uint8, RGB order (None when generated without images)
    depth:    H x W float32 metres along the optical axis, NaN where the sensor has no reading:
              exactly what a reader of the dataset gets (1/5000 m steps, as the PNG stores it)
    pose:     4 x 4 camera-to-world ground truth (optical frame: x right, y down, z forward);
              None when groundtruth.txt has no row at the frame's stamp (a plain TUM
              dataset's motion capture runs at other stamps)
    stamp_ns: the frame's time, Unix nanoseconds (``stamp`` in seconds)
    scans:    the Wi-Fi scans reported since the previous frame (before this one)
    odometry: the wheel-odometry readings since the previous frame, as (stamp_ns, 4 x 4 base
              pose in the odometry frame)
    """

    index: int
    stamp_ns: int
    rgb: Optional[np.ndarray]
    depth: Optional[np.ndarray]
    pose: Optional[np.ndarray]
    scans: Tuple[WifiScan, ...]
    odometry: Tuple[Tuple[int, np.ndarray], ...]

    @property
    def stamp(self) -> float:
        return self.stamp_ns * 1e-9


def _frame(raw: Dict[str, Any]) -> Frame:
    scans = tuple(
        WifiScan(s["stamp_ns"], s["start_ns"], s["end_ns"], s["sensor_id"],
                 tuple(WifiReading(**r) for r in s["readings"]))
        for s in raw["scans"])
    return Frame(raw["index"], raw["stamp_ns"], raw["rgb"], raw["depth"], raw["pose"], scans,
                 tuple(raw["odometry"]))


class _Pass:
    """One iteration over a frame source, from its first frame. Threads that share one pass
    take turns: each frame goes to exactly one of them."""

    def __init__(self, source):
        self._source = source
        self._number = source.begin_pass()
        self._done = False

    def __iter__(self) -> "_Pass":
        return self

    def __next__(self) -> Frame:
        if self._done:
            raise StopIteration
        raw = self._source.next_frame(self._number)
        if raw is None:
            self._done = True
            raise StopIteration
        return _frame(raw)


class _Frames:
    """The frames of a source, in route order; the source's facts as attributes.

    Every iteration (each ``for`` loop, ``list()``, ``iter()``) starts at the first frame, as a
    list's does. The frames have one read position, so one iteration runs at a time: starting
    another ends the first, whose next step raises RuntimeError rather than skip or repeat
    frames. To share the frames between threads, share one iterator: ``frames = iter(source)``.
    """

    def __init__(self, source):
        self._source = source

    def __iter__(self) -> Iterator[Frame]:
        return _Pass(self._source)

    def __len__(self) -> int:
        return self._source.frame_count

    def __repr__(self) -> str:
        return f"<wifislam.{type(self).__name__}: {self.description}, {len(self)} frames>"

    def rewind(self) -> None:
        """Put the read position back at the first frame, ending any iteration under way (an
        iteration starts there by itself)."""
        self._source.begin_pass()

    @property
    def intrinsics(self) -> Dict[str, float]:
        """Pinhole intrinsics: width_px, height_px, fx_px, fy_px, cx_px, cy_px."""
        return self._source.intrinsics

    @property
    def camera_in_base(self) -> np.ndarray:
        """4 x 4 camera pose in the robot base frame."""
        return self._source.camera_in_base

    @property
    def has_wifi(self) -> bool:
        return self._source.has_wifi

    @property
    def description(self) -> str:
        return self._source.description


class Simulator(_Frames):
    """Frames straight from the simulation of ``scene``, in route order, with no disk.

    ``seed`` and ``fps`` replace the scene's (as ``wifislam generate --seed --fps`` do);
    ``max_frames`` stops early; ``images=False`` gives frames without rgb and depth (poses and
    scans only, fast). For the same scene, seed and fps, the frames equal those a ``Dataset``
    of ``generate``'s folder returns, pixel for pixel. Each iteration simulates the route again
    from the first frame (on the world built once) and gives the same frames.
    """

    @checked
    def __init__(self, scene: Union[Scene, PathLike], seed: Optional[int] = None,
                 fps: Optional[float] = None, max_frames: int = -1, images: bool = True):
        super().__init__(_wifislam._Simulator(_scene(scene), seed, fps, max_frames, images))

    @property
    def scene(self) -> Scene:
        """The scene as simulated (seed and fps overrides applied)."""
        return self._source.scene


class Dataset(_Frames):
    """A dataset folder read as SLAM reads it: ours, or a plain TUM RGB-D one.

    Opening checks the folder as ``wifislam slam`` does (manifest SHA-256 sums unless
    ``verify=False``, every list file line by line) and raises ParseError naming the file and
    line. ``ground_truth`` is groundtruth.txt as an N x 8 array of TUM rows. A folder generated
    with ``images=False`` (``--no-images``) has a frame per ground-truth pose, the frames a
    ``Simulator`` with ``images=False`` gives: rgb and depth None.
    """

    @checked
    def __init__(self, path: PathLike, verify: bool = True, load_images: bool = True):
        # Absolute at opening: each pass reads the files again, and a later os.chdir (a
        # notebook's %cd) must not make it read another folder's.
        self.path = _absolute(_path(path, "Dataset"))
        super().__init__(_wifislam._Dataset(self.path, verify, load_images))

    @property
    def ground_truth(self) -> np.ndarray:
        return self._source.ground_truth

    @property
    def imu(self) -> Optional[np.ndarray]:
        """imu.csv as an N x 7 array: t (s), angular velocity (rad/s) x, y, z and specific force
        (m/s^2, gravity included: +9.81 up at rest) x, y, z, in the IMU frame; each row the mean
        over the time since the row before. None when the dataset has no IMU. Read (and
        checked, as ``wifislam check`` reads it) at the first access."""
        return self._source.imu

    @property
    def imu_in_base(self) -> Optional[np.ndarray]:
        """4 x 4 pose of the IMU frame in the robot base frame (calibration.yaml); None
        without an IMU. The camera's is ``camera_in_base``: the IMU in the camera's optical
        frame, Kalibr's T_cam_imu, is ``inv(camera_in_base) @ imu_in_base``."""
        return self._source.imu_in_base


def _scene(scene: Union[Scene, PathLike]) -> Scene:
    if isinstance(scene, _wifislam.Scene):
        return scene
    if _is_path(scene):
        return Scene.load(scene)
    raise TypeError(f"expected a wifislam.Scene or a scene file path, got {type(scene).__name__}")


class Renderer:
    """One scene's world on the off-screen renderer, built once for many views.

    ``render(pose)`` returns (rgb, depth) as a frame holds them; ``pose`` is a 4 x 4
    camera-to-world matrix (``camera_pose`` makes one from a position and heading). With
    ``noise=False`` the depth is ideal (no noise, quantisation or dropouts; the range applies).
    ``frame_index`` seeds the depth noise, as ``wifislam render --frame`` does.
    """

    @checked
    def __init__(self, scene: Union[Scene, PathLike]):
        self._scene = _scene(scene)
        self._renderer = _wifislam._Renderer(self._scene)

    def __repr__(self) -> str:
        return f"<wifislam.Renderer of {self._scene!r}>"

    @checked
    def render(self, pose: np.ndarray, noise: bool = True,
               frame_index: int = 0) -> Tuple[np.ndarray, np.ndarray]:
        """(rgb, depth) seen from ``pose`` (4 x 4 camera-to-world, optical frame): H x W x 3
        uint8 RGB, and H x W float32 metres with NaN where the sensor has no reading."""
        return self._renderer.render(_real_array(pose, "render(): pose"), noise, frame_index)

    @checked
    def camera_pose(self, x_m: float, y_m: float, yaw_deg: float,
                    height_m: Optional[float] = None) -> np.ndarray:
        """The 4 x 4 camera-to-world pose of the robot's camera standing at (x_m, y_m) on the
        floor plan, heading ``yaw_deg`` (0 = +x, counter-clockwise), at the camera's mounting
        height and pitch (``height_m`` replaces the height)."""
        return self._renderer.planar_pose(x_m, y_m, yaw_deg, height_m)


@checked
def render(scene: Union[Scene, PathLike], pose: np.ndarray, noise: bool = True,
           frame_index: int = 0) -> Tuple[np.ndarray, np.ndarray]:
    """One RGB-D view of ``scene`` from ``pose`` (4 x 4): (rgb H x W x 3 uint8, depth H x W
    float32 metres with NaN for no reading). Builds the world each call: use ``Renderer`` for
    many views."""
    return Renderer(scene).render(pose, noise, frame_index)


@checked
def camera_pose(scene: Union[Scene, PathLike], x_m: float, y_m: float, yaw_deg: float,
                height_m: Optional[float] = None) -> np.ndarray:
    """The 4 x 4 camera-to-world pose ``wifislam render --pose x,y,yaw`` uses: at (x, y),
    heading ``yaw_deg`` counter-clockwise from +x, at the scene camera's height and pitch
    unless ``height_m`` is given."""
    return Renderer(scene).camera_pose(x_m, y_m, yaw_deg, height_m)


@dataclasses.dataclass(frozen=True)
class RadioMap:
    """Mean RSSI over the floor plan (``wifislam radiomap``'s grid).

    rssi_dbm:   rows x cols float32, row 0 at the lowest y; NaN outside free space
    best_ap_id: rows x cols int32, the access point giving each cell's value
    origin_m:   (x, y) of cell (0, 0)'s lower-left corner; cells are resolution_m square
    """

    rssi_dbm: np.ndarray
    best_ap_id: np.ndarray
    origin_m: Tuple[float, float]
    resolution_m: float
    access_points: Tuple[Dict[str, Any], ...]

    def cell_center_m(self, col: int, row: int) -> Tuple[float, float]:
        return (self.origin_m[0] + self.resolution_m * (col + 0.5),
                self.origin_m[1] + self.resolution_m * (row + 0.5))


def _band_text(band: float) -> str:
    """A band given as a number, in GHz, as the command line spells it: 5.0 is "5", 2.4 is
    "2.4", each compared at the number's own precision (np.float32(2.4) is 2.4). Any other
    number keeps all its digits for the band check to refuse: a rounding format read
    2.40000001 as 2.4."""
    kind = band.dtype.type if isinstance(band, np.floating) else float
    for ghz, text in ((2.4, "2.4"), (5.0, "5")):
        if kind(band) == kind(ghz):
            return text
    text = repr(float(band))  # the shortest text that reads back as the number
    return text[:-2] if text.endswith(".0") else text  # "2" for 2.0, as the command line


@checked
def radio_map(scene: Union[Scene, PathLike], resolution_m: float = 0.25,
              ap: Optional[int] = None, band: Union[str, float] = "best",
              height_m: Optional[float] = None, level: Union[str, int] = "") -> RadioMap:
    """The mean RSSI (ITU-R P.1238, walls, shadowing) at every free cell: of access point
    ``ap``, or of the strongest one (``ap=None``); ``band`` is "2.4", "5" or "best"; the
    receiver at ``height_m`` (default: the camera's height, where datasets scan) above the floor
    of ``level`` (a scene with ``levels:``; default: the route's level), hearing every level's
    access points."""
    band_text = band if isinstance(band, str) else _band_text(band)
    raw = _wifislam._radio_map(_scene(scene), resolution_m, ap, band_text, height_m, str(level))
    return RadioMap(raw["rssi_dbm"], raw["best_ap_id"], tuple(raw["origin_m"]),
                    raw["resolution_m"], tuple(raw["access_points"]))


@checked
def generate(scene: Union[Scene, PathLike], output: PathLike, seed: Optional[int] = None,
             fps: Optional[float] = None, max_frames: int = -1, images: bool = True,
             threads: int = 0, force: bool = False) -> Dict[str, Any]:
    """``wifislam generate``: writes the dataset folder ``output`` and returns its summary
    (``dataset`` is the folder's absolute path; ``report`` the text the command prints).
    ``force`` replaces an existing folder of this tool's output, never anything else."""
    return _wifislam._generate(_scene(scene), _path(output, "output"), seed, fps, max_frames,
                               images, threads, force)


@checked
def slam(dataset: PathLike, output: PathLike, frontend: str = "rgbdslam", wifi: bool = False,
         settings: Optional[Mapping[str, Any]] = None, force: bool = False, verify: bool = True,
         max_frames: int = -1, fps: Optional[float] = None,
         seed: Optional[int] = None) -> Dict[str, Any]:
    """``wifislam slam``: runs a front end (``rgbdslam``, ``rtabmap``, ``orbslam`` or
    ``external:NAME``) on a dataset folder or a scene file and writes the run folder ``output``.

    ``settings`` are the ``--set`` options (``{"min_matches": 70}``). Returns ``run`` (the run
    folder's absolute path) and ``summary`` (run.json's summary) for our front ends, or
    ``external`` (status, system file, times) for an external system.
    """
    values = {str(k): _setting_text(v) for k, v in (settings or {}).items()}
    return _wifislam._slam(_path(dataset, "dataset"), _path(output, "output"), frontend, wifi,
                           values, force, verify, max_frames, fps, seed)


def _setting_text(value: Any) -> str:
    """A setting as the command line's --set spells it. numpy's scalars and arrays count as
    Python's values (a sweep over np.arange, a pandas row); a whole float is the whole number it
    holds (70.0 from a float column is min_matches 70; any number setting reads "70" alike)."""
    if isinstance(value, (np.generic, np.ndarray)):
        value = value.tolist()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):  # a number list (prune_chi2); empty is "none"
        return ",".join(_setting_text(v) for v in value) if value else "none"
    if isinstance(value, float) and value.is_integer() and abs(value) < 2**63:
        return str(int(value))
    return str(value)


TrajectoryLike = Union[PathLike, np.ndarray, Sequence[Sequence[float]]]


@checked
def evaluate(estimate: TrajectoryLike, ground_truth: TrajectoryLike, align: str = "se3",
             time_offset_s: float = 0.0, settings: Optional[Mapping[str, Any]] = None,
             verify: bool = True) -> Dict[str, Any]:
    """ATE and RPE as ``wifislam eval`` computes them, as metrics.csv's row (a dict).

    ``estimate`` is a run folder, a TUM trajectory file or an N x 8 array of TUM rows
    (t, tx, ty, tz, qx, qy, qz, qw); ``ground_truth`` a dataset folder, a TUM file or such an
    array. A run folder (or trajectory file) against a dataset folder is exactly
    ``wifislam eval RUN --gt DATASET`` (loop closures and timing included); any other pair is
    scored on the trajectories alone. ``align`` is "none", "se3" or "sim3"; ``settings`` are
    eval's ``--set`` thresholds. Array stamps are float seconds, rounded to nanoseconds.
    """
    values = {str(k): _setting_text(v) for k, v in (settings or {}).items()}
    return _wifislam._evaluate(_trajectory_arg(estimate, "estimate"),
                               _trajectory_arg(ground_truth, "ground_truth"), align,
                               float(time_offset_s), values, verify)


def _trajectory_arg(value: TrajectoryLike, what: str):
    if _is_path(value):
        return _path(value, what)
    return _real_array(value, f"evaluate(): {what}")


@checked
def require(metrics: Mapping[str, Any], *requirements: str) -> List[str]:
    """Holds metrics (``evaluate``'s dict) to requirements as ``eval --require`` does:
    "METRIC OP NUMBER" with OP one of <=, <, >=, >, ==, !=. Returns each requirement's verdict;
    raises RequirementNotMetError (an AssertionError) listing those not met and by how much,
    InvalidInputError for a malformed requirement or an unknown metric."""
    # A metric that is NaN or infinite (metrics.csv's "-nan", read back with pandas) is one the
    # run could not give: "not available", as None is, not a JSON error.
    # numpy's scalars (a pandas row) count as Python's numbers, at any depth.
    def available(value: Any) -> Any:
        if isinstance(value, (np.generic, np.ndarray)):
            value = value.tolist()
        if isinstance(value, (list, tuple)):
            return [available(v) for v in value]
        if isinstance(value, Mapping):
            return {k: available(v) for k, v in value.items()}
        if (isinstance(value, numbers.Real) and not isinstance(value, numbers.Integral)
                and not math.isfinite(value)):
            return None
        # No metric is a whole number beyond 64 bits; such a one is held as the number it is
        # near, or, beyond any double, is one the run could not give.
        if (isinstance(value, numbers.Integral) and not isinstance(value, bool)
                and not -2**63 <= value < 2**64):
            try:
                return float(value)
            except OverflowError:
                return None
        return value

    return _wifislam._require({k: available(v) for k, v in dict(metrics).items()},
                              list(requirements))


@checked
def read_trajectory(path: PathLike) -> np.ndarray:
    """A TUM trajectory file as an N x 8 array (checked as ``wifislam eval`` reads it)."""
    return _wifislam._read_trajectory(_path(path, "read_trajectory"))


def _nested_numbers(value: Any, what: str) -> np.ndarray:
    """Nested lists as numpy reads them, refused unless every element is a number: a float
    dtype would have taken strings ("1.5"), None (as NaN: no reading) and booleans silently, and
    numpy's own errors (ragged lists) name no argument."""
    try:
        array = np.asarray(value)
    except (ValueError, OverflowError) as e:
        raise _wifislam.InvalidInputError(f"{what}: not an array of numbers ({e})") from None
    if array.dtype.kind not in "iuf":
        raise _wifislam.InvalidInputError(
            f"{what}: expected numbers, got {array.dtype.name} elements")
    return array


_KIND_NAMES = {"b": "booleans", "c": "complex numbers", "U": "text", "S": "bytes",
               "M": "dates", "m": "time spans", "V": "records", "O": "objects"}


def _real_array(value: Any, what: str) -> np.ndarray:
    """Poses and trajectories as float64, refused unless every element is a real number: a
    float64 conversion dropped a complex value's imaginary part with a warning only, and read
    strings ("1.5"), booleans and None as numbers. An object array (a pandas column of mixed
    types) is taken when each element is a real number; a boolean among numbers in nested
    lists (which numpy would make 1.0) is refused."""
    def is_real(element: Any) -> bool:
        return (isinstance(element, numbers.Real)
                and not isinstance(element, (bool, np.bool_)))

    def has_boolean(nested: Any) -> bool:
        if isinstance(nested, (list, tuple)):
            return any(has_boolean(v) for v in nested)
        if isinstance(nested, np.ndarray):  # an array among the lists
            return nested.dtype.kind == "b" or (
                nested.dtype.kind == "O" and any(has_boolean(v) for v in nested.ravel()))
        return isinstance(nested, (bool, np.bool_))

    if np.ma.isMaskedArray(value) and np.ma.getmaskarray(value).any():
        # numpy would pass the hidden values on as numbers.
        raise _wifislam.InvalidInputError(
            f"{what}: has masked values; give the rows without them (numpy.ma.compress_rows)")
    try:
        array = np.asarray(value)
        kind = array.dtype.kind
        if kind == "O" and all(is_real(e) for e in array.ravel()):
            return np.array([float(e) for e in array.ravel()],
                            dtype=np.float64).reshape(array.shape)
        if kind not in "iuf":
            raise _wifislam.InvalidInputError(
                f"{what}: expected real numbers, got {_KIND_NAMES.get(kind, array.dtype.name)}")
        if not isinstance(value, np.ndarray) and has_boolean(value):
            raise _wifislam.InvalidInputError(f"{what}: expected real numbers, got a boolean")
        return array.astype(np.float64, copy=False)
    except (ValueError, OverflowError) as e:
        if isinstance(e, _wifislam.InvalidInputError):
            raise
        raise _wifislam.InvalidInputError(
            f"{what}: not an array of numbers within a float's range ({e})") from None


@checked
def encode_rgb_png(rgb: np.ndarray) -> bytes:
    """The PNG bytes ``generate`` writes for this colour image (H x W x 3 uint8 RGB)."""
    if not isinstance(rgb, np.ndarray):
        # Nested lists of whole numbers are numpy's int64: uint8 when every value fits, else
        # left for the binding to refuse. An array keeps its dtype (and the check of it).
        rgb = _nested_numbers(rgb, "encode_rgb_png(): rgb")
        if rgb.dtype.kind in "iu" and rgb.size and rgb.min() >= 0 and rgb.max() <= 255:
            rgb = rgb.astype(np.uint8)
    return _wifislam._encode_rgb_png(np.ascontiguousarray(rgb))


@checked
def encode_depth_png(depth: np.ndarray) -> bytes:
    """The 16-bit TUM depth PNG bytes (5000 per metre, 0 = no reading) ``generate`` writes for
    this depth image (H x W float metres, NaN = no reading). 16 bits at 5000 per metre end at
    13.107 m: a farther depth is stored as 0, no reading, as the dataset writer stores it."""
    if not isinstance(depth, np.ndarray):  # nested lists: metres, whole or not
        depth = _nested_numbers(depth, "encode_depth_png(): depth").astype(np.float64)
    return _wifislam._encode_depth_png(np.asarray(depth))


def __dir__() -> List[str]:
    """The public names and the module's own dunders: the helpers it imports (typing, numpy,
    os) are no API."""
    return sorted(set(__all__) | {name for name in globals() if name.startswith("__")})
