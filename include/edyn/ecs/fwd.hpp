#ifndef EDYN_ECS_FWD_HPP
#define EDYN_ECS_FWD_HPP

#include <cstdint>

/// @file
/// @brief Declarations of the ecs layer, for headers that only name its types.
namespace edyn {

enum class entity : std::uint32_t;
struct entity_traits;
struct null_t;

class sparse_set;
template<typename Type>
class storage;

template<typename>
class delegate;
template<auto Candidate>
struct connect_arg_t;
template<typename>
class sigh;
template<typename>
class sink;

template<typename... Type>
struct exclude_t;
template<typename... Type>
struct get_t;
template<typename, typename>
class basic_view;

class entity_allocator;
class context;
class registry;

} // namespace edyn

#endif // EDYN_ECS_FWD_HPP
