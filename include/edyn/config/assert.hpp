#ifndef EDYN_CONFIG_ASSERT_HPP
#define EDYN_CONFIG_ASSERT_HPP

/// @file
/// @brief The `EDYN_ASSERT` macro, edyn's debug-only check of invariants.

/// @def EDYN_ASSERT(condition, ...)
/// @brief Guards an invariant on a hot path; compiled in only when assertions are enabled.
///
/// It is compiled in when the build defines `EDYN_ASSERTIONS` (CMake option of the same name, on
/// for every build type but Release and MinSizeRel) and costs nothing otherwise: the condition is
/// then not evaluated at all, so it must have no side effects the program relies on. A failed
/// assertion prints the condition, the optional message, the file and the line to `stderr`, then
/// calls `std::abort()`. Misuse of public functions that must be reported in every build throws
/// instead (see each function's documentation).
/// @param condition Expression that must be true.
/// @param ... Optional string literal explaining the invariant, printed when it fails.

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
