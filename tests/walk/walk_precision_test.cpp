// The walker under rounding: no ping-pong, no spurious teleports, W stays rigid.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "math/portal.hpp"
#include "math/rigid.hpp"
#include "walk/walk_test_layouts.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {
namespace {

using namespace testing;
using glm::dvec3;
using math::HeadPose;

// A point over portal a's rectangle (0.2 right, 0.3 up of its centre) at
// signed distance d.
dvec3 over_a(const layout::Layout& l, double d) {
    const math::PortalRect& a = l.portals[0].rect;
    return a.center + 0.2 * math::portal_right(a) + 0.3 * a.up + d * a.normal;
}

TEST(WalkerPrecision, SkewedPairIsNotExactlyRepresentable) {
    const layout::Layout l = skewed_pair();
    const links::PortalLinks links = links::link_portals(l);
    const math::dmat4 round_trip = links.transfer[1] * links.transfer[0];
    EXPECT_NE(round_trip, math::dmat4(1.0));  // rounding is there to be survived
    EXPECT_LT(math::max_abs_difference(round_trip, math::dmat4(1.0)), 1e-13);
}

TEST(WalkerPrecision, BackAndForthTenThousandTimesWithoutPingPong) {
    const layout::Layout l = skewed_pair();
    Walker w(l);
    w.step(at(over_a(l, 0.3)));
    int through_a = 0, through_b = 0, spurious = 0;
    // Alternating long and very short steps, each followed by a frame
    // standing still, which must never teleport.
    for (int k = 0; k < 10000; ++k) {
        const double d = k % 2 == 0 ? 0.3 : 1e-12;
        const std::vector<int> in = w.step(at(over_a(l, -d)));
        if (in == std::vector<int>{0})
            ++through_a;
        else
            ++spurious;
        if (!w.step(at(over_a(l, -d))).empty()) ++spurious;
        EXPECT_EQ(w.room(), 1);
        EXPECT_GT(math::signed_distance(l.portals[1].rect, w.position()), 0.0);
        const std::vector<int> out = w.step(at(over_a(l, d)));
        if (out == std::vector<int>{1})
            ++through_b;
        else
            ++spurious;
        if (!w.step(at(over_a(l, d))).empty()) ++spurious;
        EXPECT_EQ(w.room(), 0);
        EXPECT_GT(math::signed_distance(l.portals[0].rect, w.position()), 0.0);
        if (spurious) break;
    }
    EXPECT_EQ(through_a, 10000);
    EXPECT_EQ(through_b, 10000);
    EXPECT_EQ(spurious, 0);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));  // restored exactly every time
}

// A physical position over a's rectangle (x right, y up of its centre)
// whose distance to a is the first negative double reached by stepping along
// -normal one ulp at a time from the plane.
dvec3 just_behind_a(const layout::Layout& l, double x, double y) {
    const math::PortalRect& a = l.portals[0].rect;
    dvec3 p = a.center + x * math::portal_right(a) + y * a.up;
    for (int guard = 0; guard < 100000 && math::signed_distance(a, p) >= 0.0; ++guard) {
        for (int k = 0; k < 3; ++k)
            if (a.normal[k] != 0.0) p[k] = std::nextafter(p[k], a.normal[k] > 0 ? -1e9 : 1e9);
    }
    return p;
}

TEST(WalkerPrecision, EndingAHairBehindThePlaneTeleportsOnceAndStays) {
    const layout::Layout l = skewed_pair();
    const math::PortalRect& b = l.portals[1].rect;
    // W after the teleport is the re-orthonormalised transfer matrix. Find a
    // spot where rounding leaves the mapped head on or behind b's plane,
    // so that the nudge is needed, and one where it is not.
    const math::dmat4 w_after = math::orthonormalize_rigid(links::link_portals(l).transfer[0]);
    dvec3 needs_nudge(0.0), plain(0.0);
    bool found_nudge = false, found_plain = false;
    for (int i = 0; i < 200 && !(found_nudge && found_plain); ++i) {
        for (int j = 0; j < 50 && !(found_nudge && found_plain); ++j) {
            const dvec3 p = just_behind_a(l, -0.4 + 0.004 * i, -0.9 + 0.036 * j);
            const bool nudge = math::signed_distance(b, dvec3(w_after * math::dvec4(p, 1.0))) <= 0.0;
            if (nudge && !found_nudge) needs_nudge = p, found_nudge = true;
            if (!nudge && !found_plain) plain = p, found_plain = true;
        }
    }
    ASSERT_TRUE(found_nudge);
    ASSERT_TRUE(found_plain);
    for (const dvec3& behind : {needs_nudge, plain}) {
        const double d_behind = math::signed_distance(l.portals[0].rect, behind);
        ASSERT_LT(d_behind, 0.0);
        ASSERT_GT(d_behind, -1e-15);
        Walker w(l);
        w.step(at(over_a(l, 0.5)));
        EXPECT_EQ(w.step(at(behind)), std::vector<int>{0});
        EXPECT_EQ(w.room(), 1);
        const double d_b = math::signed_distance(b, w.position());
        EXPECT_GT(d_b, 0.0);  // strictly in front of b, nudged where rounding said otherwise
        EXPECT_LT(d_b, 1e-7);
        if (&behind == &needs_nudge) {
            // Moved to about 1e-9 · (1 + |b.center|) in front.
            const double margin = 1e-9 * (1.0 + glm::length(b.center));
            EXPECT_NEAR(d_b, margin, 1e-3 * margin);
        }
        EXPECT_LT(math::orthonormality_error(w.physical_to_virtual()), 1e-15);
        for (int k = 0; k < 100; ++k) ASSERT_TRUE(w.step(at(behind)).empty()) << k;
        // A hair further is still no teleport; back to the front is one.
        EXPECT_TRUE(w.step(at(behind - 1e-9 * l.portals[0].rect.normal)).empty());
        EXPECT_EQ(w.step(at(over_a(l, 0.5))), std::vector<int>{1});
        EXPECT_EQ(w.room(), 0);
        EXPECT_GT(math::signed_distance(l.portals[0].rect, w.position()), 0.0);
    }
}

TEST(WalkerPrecision, BackAndForthRestoresWExactly) {
    // Going back through the pair just passed restores W bit for bit, so a
    // million round trips leave no drift at all.
    const layout::Layout l = skewed_pair();
    Walker w(l);
    const HeadPose front = at(over_a(l, 0.25));
    const HeadPose back = at(over_a(l, -0.25));
    w.step(front);
    constexpr int kRoundTrips = 1000000;
    int teleports = 0;
    math::dmat4 through{1.0};
    for (int k = 0; k < kRoundTrips; ++k) {
        teleports += static_cast<int>(w.step(back).size());
        if (k == 0) through = w.physical_to_virtual();
        teleports += static_cast<int>(w.step(front).size());
    }
    EXPECT_EQ(teleports, 2 * kRoundTrips);
    EXPECT_EQ(w.room(), 0);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
    EXPECT_EQ(w.position(), front.position);
    // And the way through is the transfer matrix, re-orthonormalised.
    EXPECT_LT(math::max_abs_difference(through, w.links().transfer[0]), 1e-14);
    std::printf("[ drift    ] after %d back-and-forth round trips: |W - I| = %g\n", kRoundTrips,
                math::max_abs_difference(w.physical_to_virtual(), math::dmat4(1.0)));
}

// Six overlapping rooms in a ring, r0 → r1 → ... → r5 → r0, so that walking
// the same physical loop passes a new portal every time and W is never
// restored. Room k is placed by Q^k, where Q turns 60° about a tilted axis
// through an irrational-ish point (Q⁶ = I), and every transfer matrix is Q up
// to rounding. The physical loop: walk -Z at x = 0, step to x = 3, walk +Z,
// step back. An even room holds "f" at x = 0 facing +Z (passed walking -Z)
// and the exit of the previous room's "h"; an odd room holds "h" at x = 3
// facing -Z (passed walking +Z) and the exit of the previous room's "f".
// Portal 2k is room k's entrance, 2k + 1 the exit it leads to, in room k + 1.
layout::Layout ring() {
    layout::Layout l = empty_layout("ring");
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
    const glm::dvec3 pivot(0.7071067811865476, 0.0, -1.7320508075688772);
    // Rodrigues' rotation by 60° about `axis`, through `pivot`.
    const double c = 0.5, s = std::sqrt(3.0) / 2.0;
    auto q = [&](const glm::dvec3& v, bool is_point) {
        const glm::dvec3 x = is_point ? v - pivot : v;
        const glm::dvec3 r = c * x + s * glm::cross(axis, x) + (1.0 - c) * glm::dot(axis, x) * axis;
        return is_point ? r + pivot : r;
    };
    auto q_power = [&](math::PortalRect p, int k) {
        for (int i = 0; i < k; ++i) {
            p.center = q(p.center, true);
            p.normal = glm::normalize(q(p.normal, false));
            p.up = glm::normalize(q(p.up, false));
        }
        return p;
    };
    const math::PortalRect f = make_rect({0, 1, 0}, {0, 0, 1});
    const math::PortalRect f_exit = make_rect({0, 1, 0}, {0, 0, -1});
    const math::PortalRect h = make_rect({3, 1, 0}, {0, 0, -1});
    const math::PortalRect h_exit = make_rect({3, 1, 0}, {0, 0, 1});
    for (int k = 0; k < 6; ++k) add_room(l, "r" + std::to_string(k), {-50, -50, -50}, {50, 50, 50});
    for (int k = 0; k < 6; ++k) {
        const bool even = k % 2 == 0;
        add_pair(l, (even ? "f" : "h") + std::to_string(k), k, q_power(even ? f : h, k),
                 (even ? "f_exit" : "h_exit") + std::to_string(k + 1), (k + 1) % 6,
                 q_power(even ? f_exit : h_exit, k + 1));
    }
    l.start = {0, {0, 1, 1}, 0.0};
    return l;
}

// The rotation nearest to a nearly orthonormal 3×3 part (Newton's iteration
// R ← R·(3I - RᵀR)/2 for the polar decomposition); translation kept.
math::dmat4 polar_rigid(const math::dmat4& m) {
    math::dmat3 r(m);
    for (int k = 0; k < 4; ++k) r = r * (3.0 * math::dmat3(1.0) - glm::transpose(r) * r) * 0.5;
    math::dmat4 out(r);
    out[3] = m[3];
    return out;
}

TEST(WalkerPrecision, StaysRigidOverAMillionTeleportsAroundARing) {
    const layout::Layout l = ring();
    const links::PortalLinks links = links::link_portals(l);
    // Six transfers of one rotation Q by 60°: Q⁶ = I up to rounding.
    math::dmat4 q6(1.0);
    for (int k = 0; k < 6; ++k) q6 = links.transfer[2 * k] * q6;
    ASSERT_LT(math::max_abs_difference(q6, math::dmat4(1.0)), 1e-13);
    ASSERT_NE(q6, math::dmat4(1.0));

    const HeadPose loop[4] = {at({0, 1, -1}), at({3, 1, -1}), at({3, 1, 1}), at({0, 1, 1})};
    Walker w(l);
    w.step(at({0, 1, 1}));
    constexpr int kTeleports = 1000002;  // a multiple of 6: back in r0 with W ≈ Q^6n = I
    int teleports = 0, wrong = 0;
    while (teleports < kTeleports && wrong == 0) {
        for (int s = 0; s < 4; ++s) {
            const int room = w.room();
            const std::vector<int> passed = w.step(loop[s]);
            const bool expected = (s == 0 && room % 2 == 0) || (s == 2 && room % 2 == 1);
            if (expected && passed == std::vector<int>{2 * room})
                ++teleports;
            else if (expected || !passed.empty())
                ++wrong;
        }
    }
    EXPECT_EQ(teleports, kTeleports);
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(w.room(), 0);
    // The reference: the rounded layout's own loop, (M5···M0)ⁿ by repeated
    // squaring, made rigid again by its polar decomposition (the M are
    // orthonormal only to ~1e-16, so their millionth power is not, by ~1e-10).
    // W may differ from it only by the rounding of its million products.
    math::dmat4 expected(1.0), power = q6;
    for (int n = kTeleports / 6; n > 0; n >>= 1) {
        if (n & 1) expected = power * expected;
        power = power * power;
    }
    const math::dmat4 reference = polar_rigid(expected);
    const math::dmat4& wm = w.physical_to_virtual();
    const double ortho = math::orthonormality_error(wm);
    const double drift = math::max_abs_difference(wm, reference);
    std::printf(
        "[ drift    ] after %d teleports around a ring: orthonormality %.3g, "
        "|W - polar((M5···M0)^n)| %.3g, |W - I| %.3g\n",
        kTeleports, ortho, drift, math::max_abs_difference(wm, math::dmat4(1.0)));
    EXPECT_LT(ortho, 1e-12);
    EXPECT_LT(drift, 1e-9);
}

}  // namespace
}  // namespace impossible::walk
