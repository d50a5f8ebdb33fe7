#ifndef EDYN_ECS_CONSTRUCT_HPP
#define EDYN_ECS_CONSTRUCT_HPP

#include <new>
#include <type_traits>
#include <utility>

namespace edyn {

namespace detail {

// Constructs with parentheses when the type has a matching constructor and with braces
// otherwise, so that aggregates can be created from their members' values on every compiler
// (clang 14 lacks C++20's parenthesized aggregate initialization).
template<typename Type, typename... Args>
Type *construct_component(Type *where, Args &&...args) {
    if constexpr (std::is_constructible_v<Type, Args...>) {
        return ::new (static_cast<void *>(where)) Type(std::forward<Args>(args)...);
    } else {
        return ::new (static_cast<void *>(where)) Type{std::forward<Args>(args)...};
    }
}

template<typename Type, typename... Args>
Type make_component(Args &&...args) {
    if constexpr (std::is_constructible_v<Type, Args...>) {
        return Type(std::forward<Args>(args)...);
    } else {
        return Type{std::forward<Args>(args)...};
    }
}

} // namespace detail

} // namespace edyn

#endif // EDYN_ECS_CONSTRUCT_HPP
