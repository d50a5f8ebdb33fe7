#ifndef EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP

#include "edyn/constraints/constraint_row.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/math/matrix3x3.hpp"
#include <stdexcept>
#include <string>
#include <utility>

namespace edyn {

/// Name of each constraint type in error messages ("make_constraint<point_constraint>: ...").
/// Every constraint header specialises it with the type's own name; the primary template's
/// "constraint" only shows for a type that has no specialisation.
/// @tparam T The constraint component.
template<typename T>
inline constexpr const char *constraint_type_name = "constraint";

namespace detail {

// A refusal that names an entity by its index: thrown in the asynchronous worker, it is given
// to the main thread naming the main registry's entity instead of the worker's.
struct entity_refusal : std::invalid_argument {
    entity subject;
    std::string before, after; // the message is before + index + after
    entity_refusal(entity e, std::string before_, std::string after_)
        : std::invalid_argument(before_ + std::to_string(to_index(e)) + after_)
        , subject(e)
        , before(std::move(before_))
        , after(std::move(after_)) {}
};

} // namespace detail

/// Throws std::invalid_argument with the message "make_constraint<type>: field what".
/// The validate functions of every constraint report a bad field through it, so that all their
/// messages name the function, the type and the field the same way.
/// @param type Name of the constraint type, usually `constraint_type_name<T>`.
/// @param field Name of the offending field, e.g. "pivot[0]".
/// @param what What is wrong with it, including the value received.
/// @throws std::invalid_argument Always.
[[noreturn]] void throw_constraint_error(const char *type, const char *field, const std::string &what);

/// Field check shared by the constraints' validate functions: every coordinate of `v` must be
/// finite.
/// @param type Name of the constraint type, for the message.
/// @param field Name of the field checked, for the message.
/// @param v The value checked.
/// @throws std::invalid_argument When any coordinate of `v` is infinite or NaN.
void check_constraint_finite(const char *type, const char *field, const vector3 &v);
/// Field check shared by the constraints' validate functions: `s` must be finite.
/// @param type Name of the constraint type, for the message.
/// @param field Name of the field checked, for the message.
/// @param s The value checked.
/// @throws std::invalid_argument When `s` is infinite or NaN.
void check_constraint_finite(const char *type, const char *field, scalar s);
/// Field check shared by the constraints' validate functions: `s` must be finite and at least
/// zero (stiffnesses, damping, friction torques, distances).
/// @param type Name of the constraint type, for the message.
/// @param field Name of the field checked, for the message.
/// @param s The value checked.
/// @throws std::invalid_argument When `s` is negative, infinite or NaN.
void check_constraint_non_negative(const char *type, const char *field, scalar s);
/// Field check shared by the constraints' validate functions: `s` must lie in [0, 1]
/// (restitution coefficients).
/// @param type Name of the constraint type, for the message.
/// @param field Name of the field checked, for the message.
/// @param s The value checked.
/// @throws std::invalid_argument When `s` is below 0, above 1 or NaN.
void check_constraint_unit_interval(const char *type, const char *field, scalar s);
/// Field check shared by the constraints' validate functions: the columns of `m` must form an
/// orthonormal basis (joint frames).
/// Each column's squared length must be within 1e-3 of 1 and each pair's dot product within 1e-3
/// of 0; handedness is not checked.
/// @param type Name of the constraint type, for the message.
/// @param field Name of the field checked, for the message.
/// @param m The frame checked.
/// @throws std::invalid_argument When an entry is not finite or the columns are not orthonormal.
void check_constraint_orthonormal(const char *type, const char *field, const matrix3x3 &m);
/// Field check shared by the constraints' validate functions: a finite range with `min` not
/// above `max`.
/// @param type Name of the constraint type, for the message.
/// @param min_field Name of the lower bound's field, for the message.
/// @param min The lower bound.
/// @param max_field Name of the upper bound's field, for the message.
/// @param max The upper bound.
/// @throws std::invalid_argument When either bound is infinite or NaN, or when `min > max`.
void check_constraint_range(const char *type, const char *min_field, scalar min, const char *max_field,
                            scalar max);

/// Solver indices of a constraint's two bodies; 0 (the static body) for a body the solver does
/// not move this step.
/// Filled by the constraint solver when it gathers the constraints of a step.
struct constraint_body_indices {
    /// @var a
    /// Index of body[0] in the step's solver bodies (0 for the shared static body).
    /// @var b
    /// Index of body[1] in the step's solver bodies (0 for the shared static body).
    solver_body_index a, b;
};

/// The joint anchor of pivots given in each body's object space, relative to its origin (not
/// its centre of mass, so that moving the centre of mass keeps the joints where they are).
/// Reads the bodies' `position`, `orientation` and centre of mass from the registry, once per
/// step, when the solver gathers the joints.
/// @param registry The registry holding both bodies.
/// @param body The constraint's two bodies.
/// @param pivot The pivots, in each body's object space, relative to its origin (m).
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The pivots' lever arms from each centre of mass and their separation, in world space.
joint_anchor make_joint_anchor(const registry &registry, const entity (&body)[2], const vector3 (&pivot)[2],
                               constraint_body_indices indices);

/// A frame given in a body's object space, rotated into world space.
/// @param registry The registry holding the body; its `orientation` is read.
/// @param body The body the frame is attached to.
/// @param frame The frame, columns in the body's object space.
/// @return The frame with each column in world space.
matrix3x3 world_frame(const registry &registry, entity body, const matrix3x3 &frame);

/// The check of the joints' set_axes(): an axis must be finite and not zero to give a frame.
/// @param function The function checking, for the message (e.g. "hinge_constraint::set_axes").
/// @param name The argument checked, for the message (e.g. "axisA").
/// @param axis The axis given.
/// @throws std::invalid_argument When `axis` is not finite or its length is below 1e-6.
void check_joint_axis(const char *function, const char *name, const vector3 &axis);

/// The joint frame whose first column is `axis`, normalised, completed by plane_space(): what
/// the joints' set_axes() give each body.
/// @param axis The joint's axis in one body's object space; not zero.
/// @return The orthonormal frame [axis, p, q].
matrix3x3 frame_from_axis(const vector3 &axis);

/// Rotates the columns of a world-space frame by q.
/// Used to follow a joint frame through a body's rotation since the start of the step.
/// @param q The rotation (x y z w, unit length).
/// @param frame The frame to rotate.
/// @return The frame whose columns are those of `frame` rotated by `q`.
inline matrix3x3 rotate_frame(const quaternion &q, const matrix3x3 &frame) noexcept {
    return matrix3x3_columns(rotate(q, frame.column(0)), rotate(q, frame.column(1)),
                             rotate(q, frame.column(2)));
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_BASE_HPP
