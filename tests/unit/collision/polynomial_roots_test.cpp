#include "edyn/collision/detail/cylinder_geom.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <gtest/gtest.h>
#include <random>
#include <vector>

// detail::polynomial_roots, the root finder under the cylinder tests' rim quartics: every real
// root in the interval, increasing, and the derivative's roots there on request.
namespace {

using edyn::detail::polynomial_roots;

// Coefficients, lowest power first, of the product of (x - r) over the given roots, times `lead`.
std::vector<double> from_roots(const std::vector<double> &roots, double lead = 1) {
    std::vector<double> c{lead};
    for (auto r : roots) {
        std::vector<double> next(c.size() + 1, 0.0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

double eval(const std::vector<double> &c, double x) {
    double v = 0;
    for (auto i = c.size(); i-- > 0;)
        v = v * x + c[i];
    return v;
}

std::vector<double> found(const std::vector<double> &c, double lo, double hi) {
    double roots[4];
    auto n = polynomial_roots(c.data(), int(c.size()) - 1, lo, hi, roots);
    return {roots, roots + n};
}

void expect_roots(const std::vector<double> &got, const std::vector<double> &want, double tol = 1e-9) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
        EXPECT_NEAR(got[i], want[i], tol) << "root " << i;
}

TEST(PolynomialRoots, FindsEveryRootOfAQuarticInTheIntervalInOrder) {
    expect_roots(found(from_roots({0.9, 0.2, 0.7, 0.5}), 0, 1), {0.2, 0.5, 0.7, 0.9});
    // Roots outside [lo, hi] are left out.
    expect_roots(found(from_roots({-0.5, 0.3, 1.5, 2}), 0, 1), {0.3});
    expect_roots(found(from_roots({-0.5, 0.3, 1.5, 2}), -1, 1.6), {-0.5, 0.3, 1.5});
    // A leading coefficient of any size and sign.
    expect_roots(found(from_roots({0.1, 0.4, 0.6, 0.8}, -3e4), 0, 1), {0.1, 0.4, 0.6, 0.8});
}

TEST(PolynomialRoots, CubicsQuadraticsAndLines) {
    expect_roots(found(from_roots({0.25, 0.5, 0.75}), 0, 1), {0.25, 0.5, 0.75});
    expect_roots(found(from_roots({0.1, 0.6}, 2), 0, 1), {0.1, 0.6});
    expect_roots(found(from_roots({0.3}, -5), 0, 1), {0.3});
    // No real root.
    expect_roots(found({1, 0, 1}, -10, 10), {});
    expect_roots(found({2, 0, 1, 0, 1}, -10, 10), {});
}

TEST(PolynomialRoots, VanishingLeadingCoefficientsLowerTheDegree) {
    auto c = from_roots({0.2, 0.8});
    c.push_back(0);
    c.push_back(0);
    expect_roots(found(c, 0, 1), {0.2, 0.8});
    // A constant, zero or not, has no isolated root.
    expect_roots(found({0, 0, 0, 0, 0}, 0, 1), {});
    expect_roots(found({3, 0, 0}, 0, 1), {});
}

TEST(PolynomialRoots, AnEmptyIntervalHasNoRoot) {
    expect_roots(found(from_roots({0.5, 0.6, 0.7, 0.8}), 1, 0), {});
}

TEST(PolynomialRoots, RootsAtTheEndsAreFoundOnce) {
    expect_roots(found(from_roots({0, 0.5, 1, 3}), 0, 1), {0, 0.5, 1});
}

TEST(PolynomialRoots, GivesTheExtremaInTheIntervalOnRequest) {
    // (x - 0.5)^2 (x - 0.2) (x - 0.9): the double root at 0.5 is no sign change; it is one of the
    // derivative's roots, given as an extremum.
    auto c = from_roots({0.5, 0.5, 0.2, 0.9});
    double roots[4], extrema[3];
    std::size_t num_extrema = 99;
    auto n = polynomial_roots(c.data(), 4, 0, 1, roots, extrema, &num_extrema);
    ASSERT_EQ(num_extrema, 3u);
    auto near_half =
        std::count_if(extrema, extrema + num_extrema, [](double e) { return std::abs(e - 0.5) < 1e-9; });
    EXPECT_EQ(near_half, 1);
    // Every extremum is a root of the derivative, in increasing order.
    std::vector<double> dc{c[1], 2 * c[2], 3 * c[3], 4 * c[4]};
    for (std::size_t i = 0; i < num_extrema; ++i) {
        EXPECT_NEAR(eval(dc, extrema[i]), 0, 1e-9);
        if (i > 0) {
            EXPECT_LT(extrema[i - 1], extrema[i]);
        }
    }
    // The simple roots are found; the double one may or may not be, but lies at 0.5 if it is.
    std::vector<double> got(roots, roots + n);
    EXPECT_TRUE(std::find_if(got.begin(), got.end(), [](double r) { return std::abs(r - 0.2) < 1e-9; }) !=
                got.end());
    EXPECT_TRUE(std::find_if(got.begin(), got.end(), [](double r) { return std::abs(r - 0.9) < 1e-9; }) !=
                got.end());
    for (auto r : got)
        EXPECT_TRUE(std::abs(r - 0.2) < 1e-9 || std::abs(r - 0.5) < 1e-6 || std::abs(r - 0.9) < 1e-9) << r;
    // Not asked for the extrema, it finds the same roots.
    double again[4];
    ASSERT_EQ(polynomial_roots(c.data(), 4, 0, 1, again), n);
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_EQ(again[i], roots[i]);
}

TEST(PolynomialRoots, RandomQuarticsAgainstTheirConstruction) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> root(-0.5, 1.5), lead(-4, 4);
    for (int iteration = 0; iteration < 2000; ++iteration) {
        std::vector<double> roots(4);
        for (auto &r : roots)
            r = root(rng);
        std::sort(roots.begin(), roots.end());
        // Well-separated roots only: a cluster is a near-multiple root, which moves at the rate
        // of the coefficients' rounding to the power 1/multiplicity.
        auto separated = true;
        for (std::size_t i = 1; i < roots.size(); ++i)
            separated = separated && roots[i] - roots[i - 1] > 0.05;
        if (!separated) continue;
        auto scale = lead(rng);
        if (std::abs(scale) < 0.1) continue;
        std::vector<double> want;
        for (auto r : roots) {
            if (r >= 0 && r <= 1) want.push_back(r);
        }
        expect_roots(found(from_roots(roots, scale), 0, 1), want);
    }
}

} // namespace
