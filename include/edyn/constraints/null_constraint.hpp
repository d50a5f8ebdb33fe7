#ifndef EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"

namespace edyn {

/// No rows: only an edge of the entity graph, which keeps both entities in one island (and
/// connects an external entity to a rigid body; see tag_external_entity).
/// Created with make_constraint(), which, for this type only, accepts an external entity (one
/// with `external_tag`) in place of a rigid body.
struct null_constraint {
    entity body[2]{null, null}; ///< The two joined entities, set by make_constraint() for good.
};

/// Name of null_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<null_constraint> = "null_constraint";

/// Checks a null_constraint's fields: it has none to check, so it never throws.
inline void validate_constraint(const null_constraint &) noexcept {}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_NULL_CONSTRAINT_HPP
