#pragma once
// Confidence intervals that account for shadowing shared between neighbouring positions.
//
// The fit (propagation_fit.hpp) treats its rows, the position means, as independent; but two
// positions of one AP a metre apart share most of their shadowing, so (A^T A)^-1 s^2 is too
// narrow (on a simulated survey of c_hall, N's 95 % half width was 0.33 while N varied with
// sd 0.75 between shadowing draws). Here the ordinary least-squares estimate keeps its value and
// gets the covariance it has under the fitted error model (the "sandwich"):
//   Cov = (A^T A)^-1 A^T S A (A^T A)^-1,
//   S_ij = s_mean^2 on the diagonal, sigma_s^2 exp(-d_ij / L) between two positions of the same
//          AP d_ij apart, 0 between APs (their shadowing fields are independent),
// with s_mean, sigma_s and L from shadowing_statistics.hpp. It relies on that exponential model
// and on the estimated L (if L is underestimated the intervals are still somewhat narrow).

#include "radio_model/calibrate/propagation_fit.hpp"
#include "radio_model/calibrate/shadowing_statistics.hpp"
#include "radio_model/calibrate/survey_links.hpp"

namespace wifislam::radio_model::calibrate {

/// Replaces the 95 % half widths of `fit` (N, intercepts, fitted wall losses, device offsets) by
/// the sandwich's.
void widen_for_correlated_shadowing(PropagationFit& fit, const SurveyLinks& links,
                                    const ShadowingStatistics& shadowing);

}  // namespace wifislam::radio_model::calibrate
