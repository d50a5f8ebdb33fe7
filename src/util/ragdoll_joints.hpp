#ifndef EDYN_SRC_UTIL_RAGDOLL_JOINTS_HPP
#define EDYN_SRC_UTIL_RAGDOLL_JOINTS_HPP

#include "ragdoll_layout.hpp"
#include <vector>

namespace edyn::detail {

// Joins the bodies already in `parts` with the rag doll's joints and keeps the parts that touch
// at a joint from colliding. Every entity created is also appended to `created`, so that the
// caller can take them back if something throws.
void make_ragdoll_joints(registry &registry, const ragdoll_def &def, const ragdoll_layout &layout,
                         ragdoll_entities &parts, std::vector<entity> &created);

} // namespace edyn::detail

#endif // EDYN_SRC_UTIL_RAGDOLL_JOINTS_HPP
