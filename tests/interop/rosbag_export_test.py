"""`wifislam export --for rosbag` read back with Debian's python3-rosbag, the reference reader of
ROS 1 bags: every topic with its type, one message per dataset record with the dataset's stamps,
the first colour image equal to the dataset's PNG pixel for pixel, the depth in metres (to float32
rounding) with NaN where the PNG has no reading, the Wi-Fi scans equal to wifi.csv, the custom
message's MD5 as genmsg computes it from the definition the bag carries, /tf_static latched, each
topic's header.seq counting from 0, and the odometry's twist against its own poses.

Run by CTest: rosbag_export_test.py WIFISLAM_BINARY SCRATCH_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import cv2
import genmsg
import genmsg.gentools
import genmsg.msg_loader
import numpy
import rosbag

BINARY = sys.argv[1] if len(sys.argv) > 1 else "wifislam"
SCENE = """version: 1
name: rosbag_tiny_loop
seed: 91
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [7, 0]}
  - {id: C, position_m: [7, 5]}
corridors:
  - {id: south, from: A, to: B, width_m: 2.0}
  - {id: east, from: B, to: C, width_m: 2.0}
appearance: {aliasing: 0.0, posters_per_10m: 4.0}
access_points: {placement: random, count: 6}
route:
  nodes: [A, B, C]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 4.0}
radio: {environment: office}
"""


def stamp_ns(stamp):
    return stamp.secs * 1_000_000_000 + stamp.nsecs


def tum_stamps_ns(path):
    """The stamps of a TUM list or trajectory, as integer nanoseconds (exact: 6 decimals)."""
    stamps = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            whole, _, frac = line.split()[0].partition(".")
            stamps.append(int(whole) * 1_000_000_000 + int(frac.ljust(9, "0")))
    return stamps


class RosbagExport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.root = tempfile.mkdtemp(prefix="wifislam_rosbag_")
        scene = os.path.join(cls.root, "scene.yaml")
        with open(scene, "w") as f:
            f.write(SCENE)
        cls.dataset = os.path.join(cls.root, "ds")
        subprocess.run([BINARY, "generate", scene, "--fps", "2", "--max-frames", "16", "-q",
                        "-o", cls.dataset], check=True)
        cls.out = os.path.join(cls.root, "bag")
        subprocess.run([BINARY, "export", cls.dataset, "--for", "rosbag", "-q", "-o", cls.out],
                       check=True)
        cls.bag = rosbag.Bag(os.path.join(cls.out, "dataset.bag"))

    @classmethod
    def tearDownClass(cls):
        cls.bag.close()
        shutil.rmtree(cls.root)

    def messages(self, topic):
        return [m for _, m, _ in self.bag.read_messages(topics=[topic])]

    def test_the_export_says_the_images_are_in_the_bag_and_links_nothing(self):
        with open(os.path.join(self.out, "export.json")) as f:
            export = json.load(f)
        self.assertIn("in the bag", export["links"])
        for folder, _, files in os.walk(self.out):
            for name in files:
                self.assertFalse(os.path.islink(os.path.join(folder, name)), name)

    def test_topics_types_and_counts(self):
        info = self.bag.get_type_and_topic_info().topics
        frames = len(tum_stamps_ns(os.path.join(self.dataset, "rgb.txt")))
        odometry = len(tum_stamps_ns(os.path.join(self.dataset, "odometry.txt")))
        with open(os.path.join(self.dataset, "imu.csv")) as f:
            imu_rows = sum(1 for _ in f) - 1
        expected = {
            "/camera/rgb/image_color": ("sensor_msgs/Image", frames),
            "/camera/rgb/camera_info": ("sensor_msgs/CameraInfo", frames),
            "/camera/depth/image": ("sensor_msgs/Image", frames),
            "/camera/depth/camera_info": ("sensor_msgs/CameraInfo", frames),
            "/ground_truth/pose": ("geometry_msgs/PoseStamped", frames),
            "/tf": ("tf2_msgs/TFMessage", frames + odometry),
            "/tf_static": ("tf2_msgs/TFMessage", 1),
            "/imu": ("sensor_msgs/Imu", imu_rows),
            "/odom": ("nav_msgs/Odometry", odometry),
        }
        for topic, (msg_type, count) in expected.items():
            self.assertIn(topic, info)
            self.assertEqual(info[topic].msg_type, msg_type, topic)
            self.assertEqual(info[topic].message_count, count, topic)
        self.assertEqual(info["/wifi/scan"].msg_type, "wifislam_msgs/WifiScan")
        self.assertGreater(frames, 10)
        self.assertGreater(imu_rows, 1000)

    def test_stamps_are_the_datasets(self):
        rgb = [stamp_ns(m.header.stamp) for m in self.messages("/camera/rgb/image_color")]
        self.assertEqual(rgb, tum_stamps_ns(os.path.join(self.dataset, "rgb.txt")))
        truth = [stamp_ns(m.header.stamp) for m in self.messages("/ground_truth/pose")]
        self.assertEqual(truth, tum_stamps_ns(os.path.join(self.dataset, "groundtruth.txt")))
        odom = [stamp_ns(m.header.stamp) for m in self.messages("/odom")]
        self.assertEqual(odom, tum_stamps_ns(os.path.join(self.dataset, "odometry.txt")))
        imu = [m for m in self.messages("/imu")]
        with open(os.path.join(self.dataset, "imu.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(imu), len(rows))
        for m, row in zip(imu[::50], rows[::50]):
            whole, _, frac = row["timestamp"].partition(".")
            self.assertEqual(stamp_ns(m.header.stamp),
                             int(whole) * 1_000_000_000 + int(frac.ljust(9, "0")))
            self.assertEqual(m.angular_velocity.z, float(row["w_z_radps"]))
            self.assertEqual(m.linear_acceleration.z, float(row["a_z_mps2"]))
            self.assertEqual(m.orientation_covariance[0], -1.0)
            self.assertEqual(m.header.frame_id, "imu_link")

    def test_tf_static_is_latched_and_nothing_else_is(self):
        # `rosbag play` re-advertises a topic latched only when its connection says so: without
        # it a node subscribing after the first instant never got the camera and IMU mounts.
        latching = {}
        for topic, _, _, header in self.bag.read_messages(return_connection_header=True):
            value = header.get("latching", b"0")  # python3-rosbag gives the header's bytes
            latching.setdefault(topic, set()).add(value.decode() if isinstance(value, bytes)
                                                  else value)
        self.assertEqual(latching.pop("/tf_static"), {"1"})
        for topic, values in latching.items():
            self.assertEqual(values, {"0"}, topic)

    def test_each_topics_sequence_numbers_count_its_messages(self):
        for topic in ("/camera/rgb/image_color", "/camera/depth/image", "/odom", "/imu",
                      "/ground_truth/pose", "/wifi/scan"):
            seqs = [m.header.seq for m in self.messages(topic)]
            self.assertEqual(seqs, list(range(len(seqs))), topic)

    def test_odometry_twist_is_the_bases_velocity_between_readings(self):
        odom = self.messages("/odom")
        moving = 0
        for before, after in zip(odom, odom[1:]):
            dt = (stamp_ns(after.header.stamp) - stamp_ns(before.header.stamp)) * 1e-9
            p0, p1 = before.pose.pose.position, after.pose.pose.position
            q0, q1 = before.pose.pose.orientation, after.pose.pose.orientation
            yaw0 = 2.0 * numpy.arctan2(q0.z, q0.w)
            yaw1 = 2.0 * numpy.arctan2(q1.z, q1.w)
            # The base drives on the floor: its velocity in base_link is along x at the new yaw.
            dx, dy = p1.x - p0.x, p1.y - p0.y
            forward = (numpy.cos(yaw1) * dx + numpy.sin(yaw1) * dy) / dt
            lateral = (-numpy.sin(yaw1) * dx + numpy.cos(yaw1) * dy) / dt
            turn = (yaw1 - yaw0 + numpy.pi) % (2.0 * numpy.pi) - numpy.pi
            twist = after.twist.twist
            self.assertAlmostEqual(twist.linear.x, forward, places=9)
            self.assertAlmostEqual(twist.linear.y, lateral, places=9)
            self.assertAlmostEqual(twist.angular.z, turn / dt, places=9)
            moving += abs(twist.linear.x) > 0.1
        self.assertEqual(odom[0].twist.twist.linear.x, 0.0)
        # The route drives at 0.5 m/s between pauses: most intervals move.
        self.assertGreater(moving, len(odom) // 4)

    def test_first_images_equal_the_datasets_pixel_for_pixel(self):
        with open(os.path.join(self.dataset, "associations.txt")) as f:
            first = f.readline().split()
        bgr = cv2.imread(os.path.join(self.dataset, first[1]), cv2.IMREAD_UNCHANGED)
        depth_png = cv2.imread(os.path.join(self.dataset, first[3]), cv2.IMREAD_UNCHANGED)
        image = self.messages("/camera/rgb/image_color")[0]
        self.assertEqual(image.encoding, "rgb8")
        self.assertEqual((image.height, image.width), bgr.shape[:2])
        rgb = numpy.frombuffer(image.data, dtype=numpy.uint8).reshape(image.height, image.width, 3)
        self.assertTrue(numpy.array_equal(rgb, bgr[:, :, ::-1]))
        depth = self.messages("/camera/depth/image")[0]
        self.assertEqual(depth.encoding, "32FC1")
        metres = numpy.frombuffer(depth.data, dtype="<f4").reshape(depth.height, depth.width)
        missing = depth_png == 0
        self.assertTrue(numpy.all(numpy.isnan(metres[missing])))
        self.assertFalse(numpy.any(numpy.isnan(metres[~missing])))
        # float32 metres of the PNG's 1/5000 m units (to float32 rounding).
        self.assertTrue(numpy.allclose(metres[~missing], depth_png[~missing] / 5000.0,
                                       rtol=1e-6, atol=0.0))
        info = self.messages("/camera/rgb/camera_info")[0]
        self.assertEqual(info.distortion_model, "plumb_bob")
        self.assertEqual(info.K[0], 525.0)

    def test_wifi_scans_equal_wifi_csv(self):
        with open(os.path.join(self.dataset, "wifi.csv")) as f:
            rows = list(csv.DictReader(f))
        scans = self.messages("/wifi/scan")
        self.assertGreater(len(scans), 0)
        flat = []
        for scan in scans:
            for i in range(len(scan.bssid)):
                flat.append((stamp_ns(scan.header.stamp) // 1000, scan.bssid[i],
                             scan.frequency_mhz[i], scan.rssi_dbm[i], scan.ssid[i],
                             stamp_ns(scan.scan_start) // 1000))
        expected = [(int(r["timestamp"]), r["mac_addr"], int(r["frequency_khz"]) // 1000,
                     int(r["rssi_dbm"]), r["name"], int(r["scan_time_start_us"])) for r in rows]
        self.assertEqual(flat, expected)

    def test_wifi_message_md5_matches_its_definition(self):
        connection = next(c for c in self.bag._connections.values() if c.topic == "/wifi/scan")
        definition = connection.msg_def
        own, _, dependencies = definition.partition("\n" + "=" * 80 + "\n")
        scratch = tempfile.mkdtemp(prefix="wifislam_msg_")
        try:
            os.makedirs(os.path.join(scratch, "std_msgs"))
            header_text = dependencies.split("MSG: std_msgs/Header\n", 1)[1]
            with open(os.path.join(scratch, "std_msgs", "Header.msg"), "w") as f:
                f.write(header_text)
            with open(os.path.join(scratch, "WifiScan.msg"), "w") as f:
                f.write(own)
            context = genmsg.MsgContext.create_default()
            spec = genmsg.msg_loader.load_msg_from_file(
                context, os.path.join(scratch, "WifiScan.msg"), "wifislam_msgs/WifiScan")
            genmsg.msg_loader.load_depends(context, spec,
                                           {"std_msgs": [os.path.join(scratch, "std_msgs")]})
            self.assertEqual(genmsg.gentools.compute_md5(context, spec), connection.md5sum)
        finally:
            shutil.rmtree(scratch)
        # The definition in the bag is the one shipped beside the writer.
        shipped = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "interop",
                               "rosbag", "WifiScan.msg")
        with open(shipped) as f:
            self.assertEqual(f.read(), own.rstrip("\n") + "\n")

    def test_each_other_receiver_has_a_topic_of_its_own(self):
        # wifi.csv's sensor_id names the receiver; the bag wrote every scan to /wifi/scan.
        edited = os.path.join(self.root, "two_receivers")
        shutil.copytree(self.dataset, edited, symlinks=True)
        with open(os.path.join(edited, "wifi.csv")) as f:
            rows = list(csv.DictReader(f))
        stamps = sorted({r["timestamp"] for r in rows})
        self.assertGreaterEqual(len(stamps), 2)
        for r in rows:
            if r["timestamp"] == stamps[1]:
                r["sensor_id"] = "phone_2"
        with open(os.path.join(edited, "wifi.csv"), "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
            writer.writeheader()
            writer.writerows(rows)
        out = os.path.join(self.root, "two_receivers_bag")
        subprocess.run([BINARY, "export", edited, "--for", "rosbag", "--no-verify", "-q", "-o",
                        out], check=True)
        with rosbag.Bag(os.path.join(out, "dataset.bag")) as bag:
            counts = {}
            for topic, message, _ in bag.read_messages(topics=["/wifi/scan",
                                                               "/wifi/phone_2/scan"]):
                counts.setdefault(topic, []).append(stamp_ns(message.header.stamp) // 1000)
        self.assertEqual(counts["/wifi/phone_2/scan"], [int(stamps[1])])
        self.assertEqual(counts["/wifi/scan"], [int(t) for t in stamps if t != stamps[1]])


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
