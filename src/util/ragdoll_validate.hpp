#ifndef EDYN_SRC_UTIL_RAGDOLL_VALIDATE_HPP
#define EDYN_SRC_UTIL_RAGDOLL_VALIDATE_HPP

#include "edyn/util/ragdoll.hpp"

// Checks of rag doll definitions, shared by make_ragdoll_def_from_simple and make_ragdoll.
// Each throws std::invalid_argument starting with `function`, then the field and its value.
namespace edyn::detail {

void validate_ragdoll_def(const char *function, const ragdoll_simple_def &def);
void validate_ragdoll_def(const char *function, const ragdoll_def &def);

} // namespace edyn::detail

#endif // EDYN_SRC_UTIL_RAGDOLL_VALIDATE_HPP
