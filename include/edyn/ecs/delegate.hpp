#ifndef EDYN_ECS_DELEGATE_HPP
#define EDYN_ECS_DELEGATE_HPP

#include "edyn/config/assert.hpp"
#include <functional>
#include <type_traits>
#include <utility>

namespace edyn {

/// Tag that names a function at compile time, to construct a delegate bound to it:
/// `edyn::delegate<void(int)>{edyn::connect_arg<&fn>}` or
/// `edyn::delegate{edyn::connect_arg_t<&fn>{}}`.
/// @tparam Candidate The function or member function pointer to bind.
template<auto Candidate>
struct connect_arg_t {
    /// Explicit, so that `{}` alone never converts to a tag.
    explicit connect_arg_t() = default;
};

/// The tag value of `connect_arg_t<Candidate>`, for example `edyn::connect_arg<&fn>`.
/// @tparam Candidate The function or member function pointer to bind.
template<auto Candidate>
inline constexpr connect_arg_t<Candidate> connect_arg{};

/// A non-owning handle to a callable; only the specialisation for function types,
/// `delegate<Ret(Args...)>`, is defined.
template<typename>
class delegate;

/// A non-owning handle to a function known at compile time, optionally bound to an object: a
/// free function, a member function called on an instance, or a free function that receives a
/// payload as its first argument.
///
/// It is two pointers wide, copies freely and never allocates; the caller keeps the instance or
/// payload alive while the delegate may be called.
///
/// @code
/// delegate<int(int)> d;
/// d.connect<&free_function>();          // free_function(int)
/// d.connect<&my_class::member>(object); // object.member(int); object by reference or pointer
/// d.connect<&with_payload>(payload);    // with_payload(payload, int); payload as the function
///                                       // takes it, by reference or pointer
/// @endcode
/// @tparam Ret Return type of the calls.
/// @tparam Args Argument types of the calls.
template<typename Ret, typename... Args>
class delegate<Ret(Args...)> {
public:
    /// Type of the stored function: the payload or instance first, then the call's arguments.
    using function_type = Ret(const void *, Args...);
    /// Return type of the calls.
    using result_type = Ret;

    /// An empty delegate: `bool(d)` is false and calling it is an error.
    delegate() noexcept = default;

    /// A delegate bound to a function given by a runtime pointer and an opaque payload.
    /// @param function Called as `function(payload, args...)`.
    /// @param payload Passed back to `function` unchanged; may be null.
    delegate(function_type *function, const void *payload = nullptr) noexcept
        : function(function)
        , instance(payload) {}

    /// A delegate bound to the free function `Candidate`, as `connect<Candidate>()` does.
    template<auto Candidate>
    delegate(connect_arg_t<Candidate>) noexcept {
        connect<Candidate>();
    }

    /// A delegate bound to `Candidate` and an instance or payload, as
    /// `connect<Candidate>(value_or_instance)` does.
    /// @param value_or_instance The object (member function) or payload (free function), by
    /// reference or pointer; the caller keeps it alive.
    template<auto Candidate, typename Type>
    delegate(connect_arg_t<Candidate>, Type &&value_or_instance) noexcept {
        connect<Candidate>(std::forward<Type>(value_or_instance));
    }

    /// Binds the delegate to the free function (or other constant callable) `Candidate`, called
    /// with the delegate's arguments. Fails to compile if it cannot be.
    /// @tparam Candidate Pointer to the function.
    template<auto Candidate>
    void connect() noexcept {
        static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Args...>,
                      "delegate::connect: candidate cannot be called with these arguments");
        instance = nullptr;
        function = [](const void *, Args... args) -> Ret {
            return static_cast<Ret>(std::invoke(Candidate, std::forward<Args>(args)...));
        };
    }

    /// Binds the delegate to `Candidate` and an instance or payload held by reference.
    ///
    /// `Candidate` is called as `std::invoke(Candidate, value, args...)`, which covers member
    /// functions (value is the object) and free functions taking the payload by reference.
    /// @tparam Candidate Pointer to the function or member function.
    /// @param value_or_instance The object or payload; the caller keeps it alive.
    template<auto Candidate, typename Type>
    void connect(Type &value_or_instance) noexcept {
        static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Type &, Args...>,
                      "delegate::connect: candidate cannot be called with this instance and arguments");
        instance = &value_or_instance;
        function = [](const void *payload, Args... args) -> Ret {
            auto *typed = static_cast<Type *>(const_cast<void *>(payload));
            return static_cast<Ret>(std::invoke(Candidate, *typed, std::forward<Args>(args)...));
        };
    }

    /// Binds the delegate to `Candidate` and an instance or payload given by pointer.
    ///
    /// A member function bound through a pointer is the same delegate as one bound through a
    /// reference to the object; a free function receives the pointer itself.
    /// @tparam Candidate Pointer to the function or member function.
    /// @param value_or_instance The object (must not be null for a member function) or payload.
    template<auto Candidate, typename Type>
    void connect(Type *value_or_instance) noexcept {
        if constexpr (std::is_member_pointer_v<decltype(Candidate)>) {
            EDYN_ASSERT(value_or_instance != nullptr, "delegate::connect: null instance");
            connect<Candidate>(*value_or_instance);
        } else {
            static_assert(std::is_invocable_r_v<Ret, decltype(Candidate), Type *, Args...>,
                          "delegate::connect: candidate cannot be called with this pointer and arguments");
            instance = value_or_instance;
            function = [](const void *payload, Args... args) -> Ret {
                auto *typed = static_cast<Type *>(const_cast<void *>(payload));
                return static_cast<Ret>(std::invoke(Candidate, typed, std::forward<Args>(args)...));
            };
        }
    }

    /// Binds the delegate to a function given by a runtime pointer and an opaque payload.
    /// @param fn Called as `fn(payload, args...)`.
    /// @param payload Passed back to `fn` unchanged; may be null.
    void connect(function_type *fn, const void *payload = nullptr) noexcept {
        function = fn;
        instance = payload;
    }

    /// Unbinds the delegate: it becomes empty.
    void reset() noexcept {
        function = nullptr;
        instance = nullptr;
    }

    /// The instance or payload the delegate is bound to.
    /// @return Its address, or null for a plain free function or an empty delegate.
    [[nodiscard]] const void *data() const noexcept { return instance; }

    /// Calls the bound function. The delegate must not be empty (checked by `EDYN_ASSERT`).
    /// @param args Arguments passed on to the function.
    /// @return What the function returns.
    Ret operator()(Args... args) const {
        EDYN_ASSERT(function != nullptr, "delegate: called while not connected");
        return function(instance, std::forward<Args>(args)...);
    }

    /// Whether the delegate is bound to a function.
    /// @return False for an empty delegate.
    [[nodiscard]] explicit operator bool() const noexcept { return function != nullptr; }

    /// Two delegates are equal when they call the same candidate on the same instance.
    /// @return True when the function and the instance or payload are the same.
    [[nodiscard]] friend bool operator==(const delegate &a, const delegate &b) noexcept {
        return a.function == b.function && a.instance == b.instance;
    }

private:
    function_type *function{nullptr};
    const void *instance{nullptr};
};

namespace detail {

template<typename>
struct function_signature;

template<typename Ret, typename... Args>
struct function_signature<Ret (*)(Args...)> {
    using type = Ret(Args...);
};

template<typename Ret, typename... Args>
struct function_signature<Ret (*)(Args...) noexcept> : function_signature<Ret (*)(Args...)> {};

// The signature left once the first argument is bound to a payload or instance.
template<typename>
struct bound_signature;

template<typename Ret, typename First, typename... Args>
struct bound_signature<Ret (*)(First, Args...)> {
    using type = Ret(Args...);
};

template<typename Ret, typename First, typename... Args>
struct bound_signature<Ret (*)(First, Args...) noexcept> : bound_signature<Ret (*)(First, Args...)> {};

#define EDYN_DETAIL_MEMBER_SIGNATURE(qualifiers)                                                             \
    template<typename Ret, typename Class, typename... Args>                                                 \
    struct bound_signature<Ret (Class::*)(Args...) qualifiers> {                                             \
        using type = Ret(Args...);                                                                           \
    };
EDYN_DETAIL_MEMBER_SIGNATURE()
EDYN_DETAIL_MEMBER_SIGNATURE(const)
EDYN_DETAIL_MEMBER_SIGNATURE(noexcept)
EDYN_DETAIL_MEMBER_SIGNATURE(const noexcept)
#undef EDYN_DETAIL_MEMBER_SIGNATURE

} // namespace detail

/// Deduces `delegate<Ret(Args...)>` from `delegate{connect_arg_t<&fn>{}}` for a free function.
template<auto Candidate>
delegate(connect_arg_t<Candidate>)
    -> delegate<typename detail::function_signature<decltype(Candidate)>::type>;

/// Deduces the delegate type from a candidate and an instance or payload: the candidate's
/// signature without its object or first argument.
template<auto Candidate, typename Type>
delegate(connect_arg_t<Candidate>, Type &&)
    -> delegate<typename detail::bound_signature<decltype(Candidate)>::type>;

} // namespace edyn

#endif // EDYN_ECS_DELEGATE_HPP
