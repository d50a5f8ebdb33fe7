#ifndef EDYN_ECS_ECS_HPP
#define EDYN_ECS_ECS_HPP

/// @file
/// @brief The whole ecs layer: entities, the registry, its pools and views, signals and
/// context variables.
#include "edyn/ecs/construct.hpp"
#include "edyn/ecs/context.hpp"
#include "edyn/ecs/delegate.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_allocator.hpp"
#include "edyn/ecs/entity_members.hpp"
#include "edyn/ecs/fwd.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/ecs/sigh.hpp"
#include "edyn/ecs/sink.hpp"
#include "edyn/ecs/sparse_set.hpp"
#include "edyn/ecs/storage.hpp"
#include "edyn/ecs/type_info.hpp"
#include "edyn/ecs/view.hpp"

#endif // EDYN_ECS_ECS_HPP
