#pragma once

// Work the CPU does while the operator waits (a correction's retraining of the classifier, in
// the frame before its edit shows) split over the CPU's cores. The caller's body must write only
// what its index owns, so that the result is the same for any number of workers. GL-free.
#include <cstddef>
#include <functional>

namespace steerseg {

// The workers parallelFor uses for `count` pieces when asked for 0: the cores the hardware
// reports (1 where it reports none), at most `count`.
unsigned parallelWorkers(std::size_t count, unsigned workers = 0);

// Calls body(i) once for every i in [0, count), on up to parallelWorkers(count, workers)
// threads, the calling one among them; indices are handed out in order as workers come free.
// Returns when every call has returned; the first exception a call threw is rethrown then (the
// indices not yet handed out are skipped).
void parallelFor(std::size_t count, const std::function<void(std::size_t)>& body,
                 unsigned workers = 0);

} // namespace steerseg
