#pragma once
// Options of the ORB-SLAM-style front end. ORB-SLAM2 has these as constants in its source
// (LoopClosing.cc, KeyFrameDatabase.cc, LocalMapping.cc, ORBmatcher.cc); the defaults are those
// constants. The flat `--set` keys are listed in slam_options.cpp.
//
// Verification gates (LoopClosing::ComputeSim3): ORB-SLAM2 drops a loop candidate with fewer than
// 20 SearchByBoW matches, then needs 20 RANSAC inliers of its Sim3 solver, then 40 matches after
// SearchByProjection of the candidate's and its neighbours' map points.
//   - `min_matches` (the pipeline's verification) is the second gate: RANSAC inliers, 20 in
//     ORB-SLAM2, swept by the paper.
//   - `bow_min_matches` is the first, at ORB-SLAM2's 20.
//   - The third needs map points, which this pipeline does not keep; it is not modelled. Our
//     RANSAC already re-estimates the pose on every inlier of the pair, which is what the
//     projection search refines in ORB-SLAM2.

#include <string>

namespace wifislam::slam::frontend::orbslam {

struct OrbslamOptions {
  /// Vocabulary file (`wifislam vocab train`); empty: the shipped one
  /// (assets/vocabulary/orb_k10_l4.bin, compiled in).
  std::string vocabulary;
  /// Local mapping: the previous keyframe and up to this many of its best covisible keyframes
  /// are verified against each new keyframe (LocalMapping::CreateNewMapPoints: 10 for RGB-D).
  int local_keyframes = 10;
  /// Covisibility: inliers for two keyframes to be covisible (ORB-SLAM: 15 shared map points).
  int covisibility_min_weight = 15;
  /// Best covisible keyframes grouped with a loop candidate (KeyFrameDatabase: 10).
  int covisibility_group_size = 10;
  /// Consecutive keyframes a loop candidate's group must stay consistent (LoopClosing: 3).
  int loop_consistency = 3;
  /// Keyframes after an accepted loop closure before loop detection runs again, and keyframes
  /// in the map before it runs at all (LoopClosing::DetectLoop: 10).
  int keyframes_between_loops = 10;
  /// SearchByBoW matches a loop candidate needs before verification (ComputeSim3: 20).
  int bow_min_matches = 20;
};

}  // namespace wifislam::slam::frontend::orbslam
