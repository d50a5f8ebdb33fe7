#ifndef EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"

namespace edyn {

// No rows: only an edge of the entity graph, which keeps both entities in one island (and
// connects an external entity to a rigid body; see tag_external_entity).
struct null_constraint {
    entity body[2]{null, null};
};

template<>
inline constexpr const char *constraint_type_name<null_constraint> = "null_constraint";

inline void validate_constraint(const null_constraint &) noexcept {}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP
