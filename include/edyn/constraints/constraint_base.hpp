#ifndef EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP

#include "edyn/constraints/constraint_row.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/math/matrix3x3.hpp"
#include <string>

namespace edyn {

// Name of each constraint type in error messages ("make_constraint<point_constraint>: ...").
template<typename T>
inline constexpr const char *constraint_type_name = "constraint";

// Throws std::invalid_argument "make_constraint<type>: field what".
[[noreturn]] void throw_constraint_error(const char *type, const char *field, const std::string &what);

// Field checks shared by the constraints' validate functions; each throws naming the field.
void check_constraint_finite(const char *type, const char *field, const vector3 &v);
void check_constraint_finite(const char *type, const char *field, scalar s);
void check_constraint_non_negative(const char *type, const char *field, scalar s);
void check_constraint_unit_interval(const char *type, const char *field, scalar s);
void check_constraint_orthonormal(const char *type, const char *field, const matrix3x3 &m);
void check_constraint_range(const char *type, const char *min_field, scalar min, const char *max_field,
                            scalar max);

// Solver indices of a constraint's two bodies; 0 (the static body) for a body the solver does
// not move this step.
struct constraint_body_indices {
    solver_body_index a, b;
};

// The joint anchor of pivots given in each body's object space, relative to its origin (not
// its centre of mass, so that moving the centre of mass keeps the joints where they are).
joint_anchor make_joint_anchor(const registry &registry, const entity (&body)[2], const vector3 (&pivot)[2],
                               constraint_body_indices indices);

// A frame given in a body's object space, rotated into world space.
matrix3x3 world_frame(const registry &registry, entity body, const matrix3x3 &frame);

// Rotates the columns of a world-space frame by q.
inline matrix3x3 rotate_frame(const quaternion &q, const matrix3x3 &frame) noexcept {
    return matrix3x3_columns(rotate(q, frame.column(0)), rotate(q, frame.column(1)),
                             rotate(q, frame.column(2)));
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP
