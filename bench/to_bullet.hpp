#ifndef EDYN_BENCH_TO_BULLET_HPP
#define EDYN_BENCH_TO_BULLET_HPP

// edyn's vectors and matrices as Bullet's, for the Bullet side of edyn-bench.

#include <LinearMath/btMatrix3x3.h>
#include <LinearMath/btVector3.h>
#include <edyn/math/matrix3x3.hpp>
#include <edyn/math/vector3.hpp>

namespace edyn_bench {

inline btVector3 to_bt(const edyn::vector3 &v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }

inline btMatrix3x3 to_bt(const edyn::matrix3x3 &m) {
    return {btScalar(m[0][0]), btScalar(m[0][1]), btScalar(m[0][2]), btScalar(m[1][0]), btScalar(m[1][1]),
            btScalar(m[1][2]), btScalar(m[2][0]), btScalar(m[2][1]), btScalar(m[2][2])};
}

} // namespace edyn_bench

#endif // EDYN_BENCH_TO_BULLET_HPP
