#ifndef EDYN_CONFIG_ASSERT_HPP
#define EDYN_CONFIG_ASSERT_HPP

// EDYN_ASSERT guards invariants on hot paths. It is compiled in when the build defines
// EDYN_ASSERTIONS (CMake option of the same name, on for every build type but Release and
// MinSizeRel) and costs nothing otherwise. A failed assertion prints the condition and aborts.

#if defined(EDYN_ASSERTIONS) && EDYN_ASSERTIONS
#include <cstdio>
#include <cstdlib>

namespace edyn::detail {
[[noreturn]] inline void assertion_failed(const char *condition, const char *message, const char *file,
                                          int line) {
    std::fprintf(stderr, "edyn assertion failed: %s (%s) at %s:%d\n", condition, message, file, line);
    std::abort();
}
} // namespace edyn::detail

#define EDYN_ASSERT(condition, ...)                                                                          \
    ((condition) ? void(0) : ::edyn::detail::assertion_failed(#condition, "" __VA_ARGS__, __FILE__, __LINE__))
#else
#define EDYN_ASSERT(condition, ...) void(0)
#endif

#endif // EDYN_CONFIG_ASSERT_HPP
