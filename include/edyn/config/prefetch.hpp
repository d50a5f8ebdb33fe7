#ifndef EDYN_CONFIG_PREFETCH_HPP
#define EDYN_CONFIG_PREFETCH_HPP

/// @file
/// @brief `edyn::prefetch`, a hint that brings memory into the cache ahead of its use.

#include <cstddef>
#include <cstdint>

namespace edyn {

/// Size in bytes of a cache line on the CPUs edyn is tuned for.
inline constexpr std::size_t cache_line_size = 64;

/// @brief Asks the CPU to start loading the cache lines that hold `[address, address + bytes)`.
///
/// Loops that visit objects in an order the hardware cannot guess (manifolds by island, bodies by
/// entity index) call it a few iterations ahead, so that the loads overlap the work in between.
/// It is only a hint: it never faults, whatever the address, and changes no result. Compilers
/// without a prefetch builtin make it a no-op.
/// @param address First byte wanted.
/// @param bytes How many bytes from there (at least one line is fetched).
inline void prefetch(const void *address, std::size_t bytes = 1) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    auto first = reinterpret_cast<std::uintptr_t>(address) & ~std::uintptr_t(cache_line_size - 1);
    auto last = reinterpret_cast<std::uintptr_t>(address) + (bytes > 0 ? bytes - 1 : 0);
    for (auto line = first; line <= last; line += cache_line_size)
        __builtin_prefetch(reinterpret_cast<const void *>(line));
#else
    (void)address;
    (void)bytes;
#endif
}

} // namespace edyn

#endif // EDYN_CONFIG_PREFETCH_HPP
