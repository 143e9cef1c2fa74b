#pragma once
// The radio model's defaults, written once: PropagationOptions and WifiScannerOptions start from
// them, and so do the scene's `radio` and `sensors.wifi` blocks (sim/scene/scene.hpp), whose keys
// fill those options (sim/site/radio_options.hpp).

namespace wifislam::radio_model::defaults {

/// Gudmundson decorrelation distance of the shadowing.
inline constexpr double kShadowingDecorrelationM = 3.0;
/// Fast fading of each radio (fading_process.hpp) and its coherence time at a still receiver.
inline constexpr double kFastFadingSigmaDb = 2.0;
inline constexpr double kFadingCoherenceS = 3.0;
/// Per BSSID and scan spread on top of its radio's fading.
inline constexpr double kBssidSpreadDb = 0.5;
/// Extra loss from people walking: off.
inline constexpr double kPeopleDisturbanceDb = 0.0;
/// Typical 802.11 receiver floor for beacons at 1 Mb/s.
inline constexpr double kSensitivityDbm = -92.0;
/// Passive-scan dwell per channel: 100 ms, just under one 102.4 ms beacon interval, so a dwell
/// does not always catch an AP's beacon (wifi_scanner.cpp draws whether it does).
inline constexpr double kDwellPerChannelS = 0.1;

}  // namespace wifislam::radio_model::defaults
