#ifndef EDYN_SRC_MATH_WIDE_SCALAR_HPP
#define EDYN_SRC_MATH_WIDE_SCALAR_HPP

// Several scalars handled at once, for solvers that work on independent constraints side by
// side: four, or eight in a build with EDYN_AVX2. Every operation is the IEEE operation of its
// scalar counterpart, lane by lane, without fused multiply-adds, so that a lane computes exactly
// what the scalar code computes for the same inputs, and a build gives one result whichever path
// it compiles (AVX2 or SSE2 registers on x86-64, for float or double; plain arrays elsewhere).

#include "edyn/math/scalar.hpp"
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(EDYN_AVX2) && !defined(__AVX2__)
#error "EDYN_AVX2 needs the library compiled with -mavx2 (the CMake option EDYN_AVX2 does both)"
#endif
#if defined(EDYN_AVX2) && !defined(EDYN_DOUBLE_PRECISION)
#define EDYN_WIDE_AVX2 1
#include <immintrin.h>
#elif defined(__SSE2__) && !defined(EDYN_DOUBLE_PRECISION)
#define EDYN_WIDE_SSE2 1
#include <emmintrin.h>
#elif defined(EDYN_AVX2)
#define EDYN_WIDE_DOUBLE_AVX 1 // eight doubles in two registers of four
#include <immintrin.h>
#elif defined(__SSE2__)
#define EDYN_WIDE_DOUBLE_SSE2 1 // four doubles in two registers of two
#include <emmintrin.h>
#endif

namespace edyn::detail {

// For the helpers on several wide values: a double build's wide3 spans six registers, and the
// compiler then leaves such helpers out of line unless told, passing their values through memory.
#if defined(__GNUC__)
#define EDYN_WIDE_INLINE [[gnu::always_inline]] inline
#else
#define EDYN_WIDE_INLINE inline
#endif

#ifdef EDYN_AVX2
inline constexpr std::size_t wide_lanes = 8;
#else
inline constexpr std::size_t wide_lanes = 4;
#endif

#ifdef EDYN_WIDE_AVX2

struct wide_mask {
    __m256 m;
};

struct wide {
    __m256 v;
};

inline wide wide_load(const scalar *p) noexcept { return {_mm256_loadu_ps(p)}; }
inline void wide_store(scalar *p, wide a) noexcept { _mm256_storeu_ps(p, a.v); }
inline wide wide_set(scalar s) noexcept { return {_mm256_set1_ps(s)}; }
// Eight unsigned counts (below 2^31) as scalars.
inline wide wide_from_counts(const std::uint32_t *p) noexcept {
    return {_mm256_cvtepi32_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i *>(p)))};
}
inline wide operator+(wide a, wide b) noexcept { return {_mm256_add_ps(a.v, b.v)}; }
inline wide operator-(wide a, wide b) noexcept { return {_mm256_sub_ps(a.v, b.v)}; }
inline wide operator*(wide a, wide b) noexcept { return {_mm256_mul_ps(a.v, b.v)}; }
inline wide operator/(wide a, wide b) noexcept { return {_mm256_div_ps(a.v, b.v)}; }
inline wide operator-(wide a) noexcept { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }
// a < b, lane by lane.
inline wide_mask operator<(wide a, wide b) noexcept { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OS)}; }
// Lanes of `a` where the mask is set, of `b` elsewhere.
inline wide select(wide_mask m, wide a, wide b) noexcept { return {_mm256_blendv_ps(b.v, a.v, m.m)}; }
inline wide_mask operator&(wide_mask a, wide_mask b) noexcept { return {_mm256_and_ps(a.m, b.m)}; }
inline wide_mask operator|(wide_mask a, wide_mask b) noexcept { return {_mm256_or_ps(a.m, b.m)}; }
// std::sqrt in every lane (correctly rounded, as the scalar one).
inline wide wide_sqrt(wide a) noexcept { return {_mm256_sqrt_ps(a.v)}; }
inline bool any(wide_mask m) noexcept { return _mm256_movemask_ps(m.m) != 0; }
// std::max(a, b), that is (a < b) ? b : a, in every lane (zeros' signs and NaNs included).
inline wide std_max(wide a, wide b) noexcept { return {_mm256_max_ps(b.v, a.v)}; }
// std::clamp(a, lo, hi) for lo <= hi: (a < lo) ? lo : (hi < a) ? hi : a.
inline wide std_clamp(wide a, wide lo, wide hi) noexcept {
    return {_mm256_min_ps(hi.v, _mm256_max_ps(lo.v, a.v))};
}

// Rows to columns: afterwards r[k]'s lane i holds what r[i]'s lane k held.
inline void transpose(__m256 (&r)[8]) noexcept {
    __m256 t[8], u[8];
    for (int i = 0; i < 8; i += 2) {
        t[i] = _mm256_unpacklo_ps(r[i], r[i + 1]);
        t[i + 1] = _mm256_unpackhi_ps(r[i], r[i + 1]);
    }
    for (int i = 0; i < 8; i += 4) {
        u[i] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(1, 0, 1, 0));
        u[i + 1] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(3, 2, 3, 2));
        u[i + 2] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(1, 0, 1, 0));
        u[i + 3] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    for (int i = 0; i < 4; ++i) {
        r[i] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x20);
        r[i + 4] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x31);
    }
}

#elif defined(EDYN_WIDE_SSE2)

struct wide_mask {
    __m128 m;
};

struct wide {
    __m128 v;
};

inline wide wide_load(const scalar *p) noexcept { return {_mm_loadu_ps(p)}; }
inline void wide_store(scalar *p, wide a) noexcept { _mm_storeu_ps(p, a.v); }
inline wide wide_set(scalar s) noexcept { return {_mm_set1_ps(s)}; }
// Four unsigned counts (below 2^31) as scalars.
inline wide wide_from_counts(const std::uint32_t *p) noexcept {
    return {_mm_cvtepi32_ps(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)))};
}
inline wide operator+(wide a, wide b) noexcept { return {_mm_add_ps(a.v, b.v)}; }
inline wide operator-(wide a, wide b) noexcept { return {_mm_sub_ps(a.v, b.v)}; }
inline wide operator*(wide a, wide b) noexcept { return {_mm_mul_ps(a.v, b.v)}; }
inline wide operator/(wide a, wide b) noexcept { return {_mm_div_ps(a.v, b.v)}; }
inline wide operator-(wide a) noexcept { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
// a < b, lane by lane.
inline wide_mask operator<(wide a, wide b) noexcept { return {_mm_cmplt_ps(a.v, b.v)}; }
// Lanes of `a` where the mask is set, of `b` elsewhere.
inline wide select(wide_mask m, wide a, wide b) noexcept {
    return {_mm_or_ps(_mm_and_ps(m.m, a.v), _mm_andnot_ps(m.m, b.v))};
}
inline wide_mask operator&(wide_mask a, wide_mask b) noexcept { return {_mm_and_ps(a.m, b.m)}; }
inline wide_mask operator|(wide_mask a, wide_mask b) noexcept { return {_mm_or_ps(a.m, b.m)}; }
// std::sqrt in every lane (correctly rounded, as the scalar one).
inline wide wide_sqrt(wide a) noexcept { return {_mm_sqrt_ps(a.v)}; }
inline bool any(wide_mask m) noexcept { return _mm_movemask_ps(m.m) != 0; }
// std::max(a, b), that is (a < b) ? b : a, in every lane (zeros' signs and NaNs included).
inline wide std_max(wide a, wide b) noexcept { return {_mm_max_ps(b.v, a.v)}; }
// std::clamp(a, lo, hi) for lo <= hi: (a < lo) ? lo : (hi < a) ? hi : a.
inline wide std_clamp(wide a, wide lo, wide hi) noexcept { return {_mm_min_ps(hi.v, _mm_max_ps(lo.v, a.v))}; }

#elif defined(EDYN_WIDE_DOUBLE_AVX) || defined(EDYN_WIDE_DOUBLE_SSE2)

// The lanes of a double-precision build: two registers, each holding half of them. The
// operations on one register are the same four or two IEEE operations the scalar code does.
#ifdef EDYN_WIDE_DOUBLE_AVX
using wide_half = __m256d;
inline wide_half half_load(const double *p) noexcept { return _mm256_loadu_pd(p); }
inline void half_store(double *p, wide_half a) noexcept { _mm256_storeu_pd(p, a); }
inline wide_half half_set(double s) noexcept { return _mm256_set1_pd(s); }
inline wide_half half_from_counts(const std::uint32_t *p) noexcept {
    return _mm256_cvtepi32_pd(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)));
}
inline wide_half half_add(wide_half a, wide_half b) noexcept { return _mm256_add_pd(a, b); }
inline wide_half half_sub(wide_half a, wide_half b) noexcept { return _mm256_sub_pd(a, b); }
inline wide_half half_mul(wide_half a, wide_half b) noexcept { return _mm256_mul_pd(a, b); }
inline wide_half half_div(wide_half a, wide_half b) noexcept { return _mm256_div_pd(a, b); }
inline wide_half half_xor(wide_half a, wide_half b) noexcept { return _mm256_xor_pd(a, b); }
inline wide_half half_and(wide_half a, wide_half b) noexcept { return _mm256_and_pd(a, b); }
inline wide_half half_or(wide_half a, wide_half b) noexcept { return _mm256_or_pd(a, b); }
inline wide_half half_less(wide_half a, wide_half b) noexcept { return _mm256_cmp_pd(a, b, _CMP_LT_OS); }
inline wide_half half_select(wide_half m, wide_half a, wide_half b) noexcept {
    return _mm256_blendv_pd(b, a, m);
}
inline wide_half half_sqrt(wide_half a) noexcept { return _mm256_sqrt_pd(a); }
inline wide_half half_max(wide_half a, wide_half b) noexcept { return _mm256_max_pd(a, b); }
inline wide_half half_min(wide_half a, wide_half b) noexcept { return _mm256_min_pd(a, b); }
inline int half_movemask(wide_half m) noexcept { return _mm256_movemask_pd(m); }
#else
using wide_half = __m128d;
inline wide_half half_load(const double *p) noexcept { return _mm_loadu_pd(p); }
inline void half_store(double *p, wide_half a) noexcept { _mm_storeu_pd(p, a); }
inline wide_half half_set(double s) noexcept { return _mm_set1_pd(s); }
inline wide_half half_from_counts(const std::uint32_t *p) noexcept {
    return _mm_cvtepi32_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)));
}
inline wide_half half_add(wide_half a, wide_half b) noexcept { return _mm_add_pd(a, b); }
inline wide_half half_sub(wide_half a, wide_half b) noexcept { return _mm_sub_pd(a, b); }
inline wide_half half_mul(wide_half a, wide_half b) noexcept { return _mm_mul_pd(a, b); }
inline wide_half half_div(wide_half a, wide_half b) noexcept { return _mm_div_pd(a, b); }
inline wide_half half_xor(wide_half a, wide_half b) noexcept { return _mm_xor_pd(a, b); }
inline wide_half half_and(wide_half a, wide_half b) noexcept { return _mm_and_pd(a, b); }
inline wide_half half_or(wide_half a, wide_half b) noexcept { return _mm_or_pd(a, b); }
inline wide_half half_less(wide_half a, wide_half b) noexcept { return _mm_cmplt_pd(a, b); }
inline wide_half half_select(wide_half m, wide_half a, wide_half b) noexcept {
    return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b));
}
inline wide_half half_sqrt(wide_half a) noexcept { return _mm_sqrt_pd(a); }
inline wide_half half_max(wide_half a, wide_half b) noexcept { return _mm_max_pd(a, b); }
inline wide_half half_min(wide_half a, wide_half b) noexcept { return _mm_min_pd(a, b); }
inline int half_movemask(wide_half m) noexcept { return _mm_movemask_pd(m); }
#endif
inline constexpr std::size_t half_lanes = wide_lanes / 2;
static_assert(sizeof(wide_half) == half_lanes * sizeof(double));

struct wide_mask {
    wide_half lo, hi;
};

struct wide {
    wide_half lo, hi;
};

inline wide wide_load(const scalar *p) noexcept { return {half_load(p), half_load(p + half_lanes)}; }
inline void wide_store(scalar *p, wide a) noexcept {
    half_store(p, a.lo);
    half_store(p + half_lanes, a.hi);
}
inline wide wide_set(scalar s) noexcept { return {half_set(s), half_set(s)}; }
// Unsigned counts (below 2^31) as scalars.
inline wide wide_from_counts(const std::uint32_t *p) noexcept {
    return {half_from_counts(p), half_from_counts(p + half_lanes)};
}
inline wide operator+(wide a, wide b) noexcept { return {half_add(a.lo, b.lo), half_add(a.hi, b.hi)}; }
inline wide operator-(wide a, wide b) noexcept { return {half_sub(a.lo, b.lo), half_sub(a.hi, b.hi)}; }
inline wide operator*(wide a, wide b) noexcept { return {half_mul(a.lo, b.lo), half_mul(a.hi, b.hi)}; }
inline wide operator/(wide a, wide b) noexcept { return {half_div(a.lo, b.lo), half_div(a.hi, b.hi)}; }
inline wide operator-(wide a) noexcept {
    auto sign = half_set(-0.0);
    return {half_xor(a.lo, sign), half_xor(a.hi, sign)};
}
// a < b, lane by lane.
inline wide_mask operator<(wide a, wide b) noexcept { return {half_less(a.lo, b.lo), half_less(a.hi, b.hi)}; }
// Lanes of `a` where the mask is set, of `b` elsewhere.
inline wide select(wide_mask m, wide a, wide b) noexcept {
    return {half_select(m.lo, a.lo, b.lo), half_select(m.hi, a.hi, b.hi)};
}
inline wide_mask operator&(wide_mask a, wide_mask b) noexcept {
    return {half_and(a.lo, b.lo), half_and(a.hi, b.hi)};
}
inline wide_mask operator|(wide_mask a, wide_mask b) noexcept {
    return {half_or(a.lo, b.lo), half_or(a.hi, b.hi)};
}
// std::sqrt in every lane (correctly rounded, as the scalar one).
inline wide wide_sqrt(wide a) noexcept { return {half_sqrt(a.lo), half_sqrt(a.hi)}; }
inline bool any(wide_mask m) noexcept { return (half_movemask(m.lo) | half_movemask(m.hi)) != 0; }
// std::max(a, b), that is (a < b) ? b : a, in every lane (zeros' signs and NaNs included).
inline wide std_max(wide a, wide b) noexcept { return {half_max(b.lo, a.lo), half_max(b.hi, a.hi)}; }
// std::clamp(a, lo, hi) for lo <= hi: (a < lo) ? lo : (hi < a) ? hi : a.
inline wide std_clamp(wide a, wide lo, wide hi) noexcept {
    return {half_min(hi.lo, half_max(lo.lo, a.lo)), half_min(hi.hi, half_max(lo.hi, a.hi))};
}

#else

struct wide_mask {
    bool m[wide_lanes];
};

struct wide {
    scalar v[wide_lanes];
};

template<typename Fn>
inline wide lanewise(Fn fn) noexcept {
    wide r;
    for (std::size_t i = 0; i < wide_lanes; ++i)
        r.v[i] = fn(i);
    return r;
}

inline wide wide_load(const scalar *p) noexcept {
    return lanewise([&](std::size_t i) { return p[i]; });
}
inline void wide_store(scalar *p, wide a) noexcept {
    for (std::size_t i = 0; i < wide_lanes; ++i)
        p[i] = a.v[i];
}
inline wide wide_set(scalar s) noexcept {
    return lanewise([&](std::size_t) { return s; });
}
inline wide wide_from_counts(const std::uint32_t *p) noexcept {
    return lanewise([&](std::size_t i) { return scalar(p[i]); });
}
inline wide operator+(wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return a.v[i] + b.v[i]; });
}
inline wide operator-(wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return a.v[i] - b.v[i]; });
}
inline wide operator*(wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return a.v[i] * b.v[i]; });
}
inline wide operator/(wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return a.v[i] / b.v[i]; });
}
inline wide operator-(wide a) noexcept {
    return lanewise([&](std::size_t i) { return -a.v[i]; });
}
inline wide_mask operator<(wide a, wide b) noexcept {
    wide_mask m;
    for (std::size_t i = 0; i < wide_lanes; ++i)
        m.m[i] = a.v[i] < b.v[i];
    return m;
}
inline wide select(wide_mask m, wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return m.m[i] ? a.v[i] : b.v[i]; });
}
inline wide_mask operator&(wide_mask a, wide_mask b) noexcept {
    wide_mask m;
    for (std::size_t i = 0; i < wide_lanes; ++i)
        m.m[i] = a.m[i] && b.m[i];
    return m;
}
inline wide_mask operator|(wide_mask a, wide_mask b) noexcept {
    wide_mask m;
    for (std::size_t i = 0; i < wide_lanes; ++i)
        m.m[i] = a.m[i] || b.m[i];
    return m;
}
inline wide wide_sqrt(wide a) noexcept {
    return lanewise([&](std::size_t i) { return std::sqrt(a.v[i]); });
}
inline bool any(wide_mask m) noexcept {
    for (std::size_t i = 0; i < wide_lanes; ++i)
        if (m.m[i]) return true;
    return false;
}
inline wide std_max(wide a, wide b) noexcept {
    return lanewise([&](std::size_t i) { return a.v[i] < b.v[i] ? b.v[i] : a.v[i]; });
}
inline wide std_clamp(wide a, wide lo, wide hi) noexcept {
    return lanewise(
        [&](std::size_t i) { return a.v[i] < lo.v[i] ? lo.v[i] : (hi.v[i] < a.v[i] ? hi.v[i] : a.v[i]); });
}

#endif

// A vector3 in each lane.
struct wide3 {
    wide x, y, z;
};

EDYN_WIDE_INLINE wide3 operator+(const wide3 &a, const wide3 &b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
EDYN_WIDE_INLINE wide3 operator-(const wide3 &a, const wide3 &b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
EDYN_WIDE_INLINE wide3 operator*(const wide3 &a, wide s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
EDYN_WIDE_INLINE wide dot(const wide3 &a, const wide3 &b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
EDYN_WIDE_INLINE wide3 cross(const wide3 &a, const wide3 &b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
EDYN_WIDE_INLINE wide3 select(wide_mask m, const wide3 &a, const wide3 &b) noexcept {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
// Loads three arrays of lanes (x, y, z).
EDYN_WIDE_INLINE wide3 wide3_load(const scalar (&p)[3][wide_lanes]) noexcept {
    return {wide_load(p[0]), wide_load(p[1]), wide_load(p[2])};
}

// A 3x3 matrix in each lane, by rows.
struct wide_matrix3x3 {
    wide3 row[3];
};

// The matrix times a column vector in each lane, as edyn's matrix3x3 operator* computes it.
EDYN_WIDE_INLINE wide3 operator*(const wide_matrix3x3 &m, const wide3 &v) noexcept {
    return {dot(m.row[0], v), dot(m.row[1], v), dot(m.row[2], v)};
}

// A quaternion in each lane, rotating as edyn::rotate does.
struct wide_quaternion {
    wide x, y, z, w;
};

EDYN_WIDE_INLINE wide3 rotate(const wide_quaternion &q, const wide3 &v) noexcept {
    wide3 u{q.x, q.y, q.z};
    auto two = wide_set(scalar(2));
    auto t = cross(u, v) * two;
    return (v + t * q.w) + cross(u, t);
}

} // namespace edyn::detail

#endif // EDYN_SRC_MATH_WIDE_SCALAR_HPP
