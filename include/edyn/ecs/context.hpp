#ifndef EDYN_ECS_CONTEXT_HPP
#define EDYN_ECS_CONTEXT_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/construct.hpp"
#include "edyn/ecs/type_info.hpp"
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace edyn {

/// Context variables of a registry (`registry.ctx()`): at most one value per type, owned by the
/// context, for state that belongs to a registry as a whole rather than to an entity (edyn keeps
/// its settings and per-world state there).
///
/// Values are allocated one by one and never move: references stay valid until that value is
/// erased or the context is destroyed. Values are destroyed in the reverse order of their
/// creation, so a value may refer to values created before it. A context is not thread-safe.
class context {
public:
    context() = default;
    context(const context &) = delete;
    context &operator=(const context &) = delete;
    /// Takes over the values of `other`, which is left empty; references to them stay valid.
    context(context &&) noexcept = default;
    /// Destroys this context's values (newest first), then takes over those of `other`.
    /// @param other The context to move from; left empty.
    /// @return This context.
    context &operator=(context &&other) noexcept {
        if (this != &other) {
            clear();
            entries = std::move(other.entries);
            slots = std::move(other.slots);
        }
        return *this;
    }
    ~context() { clear(); }

    /// Creates the value of type `Type` from `args` and returns it; if there already is one, it
    /// is returned unchanged and `args` are ignored (as EnTT does).
    /// @tparam Type The variable's type, neither a reference nor cv-qualified.
    /// @param args Constructor arguments (parentheses, or braces for aggregates).
    /// @return The value of type `Type`.
    template<typename Type, typename... Args>
    Type &emplace(Args &&...args) {
        if (auto *existing = find<Type>()) {
            return *existing;
        }
        return insert<Type>(std::forward<Args>(args)...);
    }

    /// Creates the value or replaces the existing one with a new value built from `args`
    /// (assigned, so references to it stay valid).
    /// @tparam Type The variable's type, neither a reference nor cv-qualified.
    /// @param args Constructor arguments (parentheses, or braces for aggregates).
    /// @return The value of type `Type`.
    template<typename Type, typename... Args>
    Type &emplace_or_replace(Args &&...args) {
        if (auto *existing = find<Type>()) {
            *existing = detail::make_component<Type>(std::forward<Args>(args)...);
            return *existing;
        }
        return insert<Type>(std::forward<Args>(args)...);
    }

    /// Stores `value` as the variable of its type (cv-qualifiers and references removed),
    /// creating it or assigning over the existing one.
    /// @param value The value to copy or move in.
    /// @return The stored value.
    template<typename Type>
    Type &insert_or_assign(Type &&value) {
        return emplace_or_replace<std::remove_cvref_t<Type>>(std::forward<Type>(value));
    }

    /// The value of type `Type`, if there is one.
    /// @return A pointer to the value, or null when the context has none.
    template<typename Type>
    [[nodiscard]] Type *find() noexcept {
        const auto id = type_index<Type>();
        if (id >= slots.size() || slots[id] == no_slot) {
            return nullptr;
        }
        return static_cast<Type *>(entries[slots[id]].value.get());
    }

    /// Read-only `find`.
    /// @return A pointer to the value, or null when the context has none.
    template<typename Type>
    [[nodiscard]] const Type *find() const noexcept {
        return const_cast<context *>(this)->find<Type>();
    }

    /// The value of type `Type`, which must exist (checked by `EDYN_ASSERT` only; use `find`
    /// when it may not).
    /// @return The value.
    template<typename Type>
    [[nodiscard]] Type &get() noexcept {
        auto *value = find<Type>();
        EDYN_ASSERT(value != nullptr, "context::get: no context variable of this type");
        return *value;
    }

    /// Read-only `get`; the value must exist.
    /// @return The value.
    template<typename Type>
    [[nodiscard]] const Type &get() const noexcept {
        return const_cast<context *>(this)->get<Type>();
    }

    /// Whether the context holds a value of type `Type`.
    /// @return True when there is one.
    template<typename Type>
    [[nodiscard]] bool contains() const noexcept {
        return find<Type>() != nullptr;
    }

    /// Destroys the value of type `Type`, if any. References to other values stay valid.
    /// @return Whether there was one.
    template<typename Type>
    bool erase() {
        const auto id = type_index<Type>();
        if (id >= slots.size() || slots[id] == no_slot) {
            return false;
        }
        const auto pos = slots[id];
        // Unlink first: the value's destructor may look at the context.
        auto removed = std::move(entries[pos]);
        entries.erase(entries.begin() + static_cast<std::ptrdiff_t>(pos));
        slots[id] = no_slot;
        for (auto &slot : slots) {
            if (slot != no_slot && slot > pos) {
                --slot;
            }
        }
        return true;
    }

    /// Number of values held.
    /// @return One per type stored.
    [[nodiscard]] std::size_t size() const noexcept { return entries.size(); }
    /// Whether the context holds no value.
    /// @return True when `size() == 0`.
    [[nodiscard]] bool empty() const noexcept { return entries.empty(); }

    /// Destroys every value, newest first.
    void clear() noexcept {
        while (!entries.empty()) {
            auto removed = std::move(entries.back());
            entries.pop_back();
            slots[removed.id] = no_slot;
        }
    }

private:
    static constexpr std::size_t no_slot = ~std::size_t{};

    using deleter_type = void (*)(void *);

    struct entry {
        std::unique_ptr<void, deleter_type> value;
        std::size_t id;
    };

    template<typename Type, typename... Args>
    Type &insert(Args &&...args) {
        static_assert(std::is_same_v<Type, std::remove_cvref_t<Type>>,
                      "context: variable types must not be references or cv-qualified");
        const auto id = type_index<Type>();
        if (id >= slots.size()) {
            slots.resize(id + 1, no_slot);
        }
        entries.reserve(entries.size() + 1);
        auto value =
            std::unique_ptr<Type>(new Type(detail::make_component<Type>(std::forward<Args>(args)...)));
        auto *pointer = value.get();
        entries.push_back({std::unique_ptr<void, deleter_type>(value.release(), &destroy<Type>), id});
        slots[id] = entries.size() - 1;
        return *pointer;
    }

    template<typename Type>
    static void destroy(void *value) noexcept {
        delete static_cast<Type *>(value);
    }

    std::vector<entry> entries;     // in order of creation
    std::vector<std::size_t> slots; // by type index: position in `entries`, or `no_slot`
};

} // namespace edyn

#endif // EDYN_ECS_CONTEXT_HPP
