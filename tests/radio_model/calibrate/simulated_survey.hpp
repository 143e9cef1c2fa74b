#pragma once
// What the calibration tests' simulated surveys share: the channel the phones scan (channel 6)
// and the height they are held at.

namespace wifislam::test {

constexpr double kSurveyFrequencyMhz = 2437.0;
constexpr double kSurveyReceiverHeightM = 1.0;

}  // namespace wifislam::test
