#ifndef EDYN_COLLISION_COLLIDE_HPP
#define EDYN_COLLISION_COLLIDE_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/shapes/shapes.hpp"

namespace edyn {

/// Closest points between a sphere (`a`) and a sphere (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a plane (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a box (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a capsule (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a cylinder (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a plane (`a`) and a sphere (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a plane (`a`) and a box (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a plane (`a`) and a capsule (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a plane (`a`) and a cylinder (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a box (`a`) and a box (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const box_shape &b, const collision_context &ctx, collision_result &result);
/// Closest points between a box (`a`) and a sphere (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a plane (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a capsule (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a cylinder (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a capsule (`a`) and a capsule (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a sphere (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a plane (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a box (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a cylinder (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a cylinder (`a`) and a cylinder (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a sphere (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a plane (`b`).
///
/// The plane ignores its own position and orientation in `ctx`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a box (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a capsule (`b`).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a polyhedron (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a sphere (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a plane (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a box (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a capsule (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a cylinder (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a plane (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a polyhedron (`b`).
///
/// Found by SAT over face normals and edge pairs; featureA and featureB are not reported.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a compound (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a sphere (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a plane (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a box (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a capsule (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a cylinder (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a polyhedron (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a sphere (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a plane (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const plane_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a compound (`b`).
///
/// Tested child by child (through the compound's tree when it has many children); features carry
/// the child index in `part`, and where the child's own pair reports no feature, the compound's
/// feature is `{std::monostate, 0, part}`.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a sphere (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const mesh_shape &b, const collision_context &ctx, collision_result &result);
/// Closest points between a polyhedron (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a triangle mesh (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a triangle mesh (`a`) and a sphere (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a triangle mesh (`a`) and a capsule (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a triangle mesh (`a`) and a cylinder (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a triangle mesh (`a`) and a box (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const box_shape &b, const collision_context &ctx, collision_result &result);
/// Closest points between a triangle mesh (`a`) and a polyhedron (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a triangle mesh (`a`) and a compound (`b`).
///
/// Against the mesh's one-sided triangles, whose inactive internal edges do not catch (see
/// triangle_mesh); features on the mesh are triangle features whose `part` is the triangle index.
/// The mesh follows its body's transform (unlike a plane).
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between a sphere (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const sphere_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a capsule (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const capsule_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a cylinder (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const cylinder_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a box (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const box_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a polyhedron (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const polyhedron_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a compound (`a`) and a paged triangle mesh (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const compound_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a sphere (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a capsule (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a cylinder (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a box (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a polyhedron (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
/// Closest points between a paged triangle mesh (`a`) and a compound (`b`).
///
/// As against a triangle mesh, but only against the pages that are loaded (see
/// paged_triangle_mesh); the mesh feature's `part` numbers the triangle across pages.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (m, unit quaternions) and the distance threshold (m).
/// @param result Receives the points within the threshold, appended (the caller clears it);
///        conventions as for the shapes_variant_t overload.
void collide(const paged_mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

/// Closest points between any two shapes a rigid body can have, whatever their types.
///
/// Points closer than `ctx.threshold` are appended to `result`, which the caller clears
/// beforehand (a default-constructed collision_result is empty); at most
/// collision_result::max_contacts are kept. Normals point from B towards A (see
/// collision_result::collision_point). Planes ignore posA/ornA (or posB/ornB), as static shapes
/// do. Two static-only shapes (planes, meshes) report nothing. No call allocates memory, so it
/// can be called from any thread on shapes nobody modifies meanwhile.
/// @param a Shape A, at `ctx.posA` and `ctx.ornA`.
/// @param b Shape B, at `ctx.posB` and `ctx.ornB`.
/// @param ctx The shapes' transforms (positions in m, unit quaternions x y z w) and the distance
///        threshold (m).
/// @param result Receives the closest points; pivots are in each shape's object space (m).
void collide(const shapes_variant_t &a, const shapes_variant_t &b, const collision_context &ctx,
             collision_result &result);

/// Swaps the roles of A and B in a context, for implementing (B, A) through (A, B).
/// @param ctx The context to swap.
/// @return A context with posA/ornA and posB/ornB exchanged and the same threshold.
constexpr collision_context swap_context(const collision_context &ctx) noexcept {
    return {ctx.posB, ctx.ornB, ctx.posA, ctx.ornA, ctx.threshold};
}

} // namespace edyn

#endif // EDYN_COLLISION_COLLIDE_HPP
