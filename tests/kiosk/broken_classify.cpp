// The app built with its classify speed broken on purpose (issue 47): the classifier's gather
// hands the inside examples' rows the outside examples' features, as an NVIDIA driver did. Only
// this test build sets the seam; a site cannot. kiosk_gpu_check_test.cpp runs it.
#include "speed/classifier_gather_fault.hpp"

namespace {

const bool broken = [] {
    steerseg::speed::fault::reverseGatheredRows(true);
    return true;
}();

} // namespace
