#pragma once

// A test seam (issue 47), not a setting: no config key, option or environment variable reaches
// it. Only the tests and the tests' deliberately broken build of the app call it, to see the
// numerics check and the comparisons fail on the fault an NVIDIA driver showed: the training
// rows of one class carrying another tissue's features.
namespace steerseg::speed::fault {

// While on, gatherClassifierFeatures hands row n the features it gathered for row count-1-n (so
// the inside examples, gathered first, get the outside examples' features and back).
void reverseGatheredRows(bool on);

} // namespace steerseg::speed::fault
