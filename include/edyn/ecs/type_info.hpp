#ifndef EDYN_ECS_TYPE_INFO_HPP
#define EDYN_ECS_TYPE_INFO_HPP

#include <atomic>
#include <cstddef>
#include <string_view>
#include <type_traits>

namespace edyn {

namespace detail {

template<typename Type>
[[nodiscard]] constexpr std::string_view pretty_function() noexcept {
    return __PRETTY_FUNCTION__;
}

// g++ writes "... pretty_function() [with Type = ns::name; std::string_view = ...]" and clang
// "... pretty_function() [Type = ns::name]": the name runs from "Type = " to the first ';' or,
// when there is none, to the closing bracket.
[[nodiscard]] constexpr std::string_view strip_pretty_function(std::string_view text) noexcept {
    constexpr std::string_view key = "Type = ";
    const auto start = text.find(key);
    if (start == std::string_view::npos) {
        return text;
    }
    const auto first = start + key.size();
    auto last = text.find(';', first);
    if (last == std::string_view::npos) {
        last = text.rfind(']');
    }
    if (last == std::string_view::npos || last < first) {
        return text.substr(first);
    }
    return text.substr(first, last - first);
}

inline std::size_t next_type_index() noexcept {
    static std::atomic<std::size_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed);
}

} // namespace detail

/// The qualified name of `Type` as the compiler spells it, for example "edyn::position".
///
/// Used in error messages; spellings of templates may differ between compilers, so never compare
/// or store the result.
/// @tparam Type Any type.
/// @return A view of a string with static storage duration.
template<typename Type>
[[nodiscard]] constexpr std::string_view type_name() noexcept {
    return detail::strip_pretty_function(detail::pretty_function<Type>());
}

/// A small integer per type, handed out 0, 1, 2, ... in order of first use in the program, so
/// that registries can keep their pools in plain arrays indexed by it.
///
/// cv-qualifiers and references are ignored. Ids are not stable across runs or builds: never
/// serialize them. Thread-safe: the counter is atomic.
/// @tparam Type Any type.
/// @return The index of `Type`, the same for the whole run of the program.
template<typename Type>
[[nodiscard]] std::size_t type_index() noexcept {
    if constexpr (!std::is_same_v<Type, std::remove_cvref_t<Type>>) {
        return type_index<std::remove_cvref_t<Type>>();
    } else {
        static const std::size_t value = detail::next_type_index();
        return value;
    }
}

} // namespace edyn

#endif // EDYN_ECS_TYPE_INFO_HPP
