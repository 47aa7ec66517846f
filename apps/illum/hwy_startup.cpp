// Debian 12's Highway (libhwy 1.0.3) measures its timer's resolution in a static initializer, for
// its nanobenchmark, which illum does not use: 3.6 ms at the start of every process that loads the
// library, a twentieth of a thumbnail's whole time (upstream defers it since google/highway#2440,
// "Defer the call to get timer resolution until needed"). The initializer calls this function
// through its PLT, so an executable that defines it and exports it (the link option beside this
// file's target) runs this one instead: nothing to measure, nothing else changed.
#include <cstdint>

namespace hwy::platform {

std::uint64_t TimerResolution() { return 1; }

}  // namespace hwy::platform
