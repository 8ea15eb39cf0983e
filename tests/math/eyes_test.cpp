// A view's eyes (math/eyes.hpp): per-eye poses relative to the head, the
// IPD rule as their special case, and quaternions.
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/eyes.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::near_vec;

bool same_bits(const Eye& a, const Eye& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.rotation, &b.rotation, sizeof a.rotation) == 0 &&
           std::memcmp(&a.head, &b.head, sizeof a.head) == 0;
}

bool near_rotation(const dmat3& a, const dmat3& b, double tol) {
    for (int c = 0; c < 3; ++c)
        if (!near_vec(a[c], b[c], tol)) return false;
    return true;
}

View view_at(const HeadPose& head, double ipd) {
    View v;
    v.head = head;
    v.ipd = ipd;
    return v;
}

// The Valve Index's eyes: ±IPD/2 along x, each turned 5° outwards about the
// vertical axis (positive yaw turns left).
std::array<EyeOffset, 2> canted(double ipd, double deg) {
    return {eye_offset(HeadPose{{-0.5 * ipd, 0.0, 0.0}, deg, 0.0, 0.0}),
            eye_offset(HeadPose{{0.5 * ipd, 0.0, 0.0}, -deg, 0.0, 0.0})};
}

TEST(ViewEyes, WithoutOffsetsTheIpdRuleBitForBit) {
    for (const HeadPose& head : {HeadPose{{0.3, 1.6, 1.6}, 8.0, 0.0, 0.0}, HeadPose{{-1e3, 1.7, 2.5}, 37.0, -12.0, 4.0},
                                 HeadPose{{0.0, 0.0, 0.0}, 90.0, 90.0, 90.0}}) {
        for (double ipd : {0.0, 0.064, 0.0724, 10.0}) {
            const std::array<Eye, 2> want = eyes_of(head, ipd);
            const std::array<Eye, 2> got = eyes_of(view_at(head, ipd));
            for (int e = 0; e < 2; ++e) EXPECT_TRUE(same_bits(got[e], want[e])) << ipd << " eye " << e;
        }
    }
}

TEST(ViewEyes, OffsetsPlaceAndTurnEachEye) {
    // The head looks along -X (yaw 90): its right is -Z, its back +X.
    const HeadPose head{{1.0, 1.6, -2.0}, 90.0, 0.0, 0.0};
    View v = view_at(head, 5.0);  // ipd is not read with offsets
    v.eye_offsets = {EyeOffset{{-0.03, 0.01, -0.02}, rotation_y_deg(5.0)},
                     EyeOffset{{0.035, -0.01, 0.0}, rotation_x_deg(-10.0)}};
    const std::array<Eye, 2> eyes = eyes_of(v);
    const dmat3 r = head_rotation(head);
    EXPECT_TRUE(near_vec(eyes[0].position, dvec3(1.0 - 0.02, 1.61, -2.0 + 0.03), 1e-15));
    EXPECT_TRUE(near_vec(eyes[1].position, dvec3(1.0, 1.59, -2.0 - 0.035), 1e-15));
    EXPECT_TRUE(near_rotation(eyes[0].rotation, r * rotation_y_deg(5.0), 1e-15));
    EXPECT_TRUE(near_rotation(eyes[1].rotation, r * rotation_x_deg(-10.0), 1e-15));
    EXPECT_EQ(eyes[0].head, head.position);  // Eye::head stays the head centre
    EXPECT_EQ(eyes[1].head, head.position);
    // The left eye turned 5° further left than the head: from -X towards -Z.
    const dvec3 f = forward_of(eyes[0].rotation);
    EXPECT_NEAR(f.x, -std::cos(radians(5.0)), 1e-15);
    EXPECT_NEAR(f.z, std::sin(radians(5.0)), 1e-15);
}

TEST(ViewEyes, CantedEyesTurnOutwards) {
    View v = view_at(HeadPose{{0.0, 1.6, 0.0}, 0.0, 0.0, 0.0}, 0.064);
    v.eye_offsets = canted(0.064, 5.0);
    const std::array<Eye, 2> eyes = eyes_of(v);
    EXPECT_NEAR(forward_of(eyes[0].rotation).x, -std::sin(radians(5.0)), 1e-15);
    EXPECT_NEAR(forward_of(eyes[1].rotation).x, std::sin(radians(5.0)), 1e-15);
    EXPECT_TRUE(near_vec(eyes[0].position, dvec3(-0.032, 1.6, 0.0), 1e-15));
    EXPECT_TRUE(near_vec(eyes[1].position, dvec3(0.032, 1.6, 0.0), 1e-15));
    // At another head, as the preview places the physical eyes.
    const HeadPose other{{2.0, 1.5, 1.0}, 0.0, 0.0, 0.0};
    EXPECT_TRUE(near_vec(eyes_of(v, other)[1].position, dvec3(2.032, 1.5, 1.0), 1e-15));
}

TEST(ViewEyes, IpdOffsetsMatchTheIpdRule) {
    const HeadPose head{{3.25, 1.7, -7.5}, 37.0, 12.0, -5.0};
    View v = view_at(head, 0.07);
    v.eye_offsets = canted(0.07, 0.0);
    const std::array<Eye, 2> want = eyes_of(head, 0.07), got = eyes_of(v);
    for (int e = 0; e < 2; ++e) {
        EXPECT_TRUE(near_vec(got[e].position, want[e].position, 1e-15));
        EXPECT_EQ(got[e].rotation, want[e].rotation);  // the identity quaternion is exact
    }
}

TEST(Quaternions, IdentityAndHalfTurnsAreExact) {
    EXPECT_EQ(quaternion_rotation(dvec4(0, 0, 0, 1)), dmat3(1.0));
    EXPECT_EQ(quaternion_rotation(dvec4(0, 1, 0, 0)), rotation_y_deg(180.0));
    EXPECT_EQ(angles_quaternion(HeadPose{}), dvec4(0, 0, 0, 1));
    EXPECT_EQ(eye_offset(HeadPose{{0.1, 0.2, 0.3}, 0.0, 0.0, 0.0}), (EyeOffset{{0.1, 0.2, 0.3}, dmat3(1.0)}));
}

TEST(Quaternions, AnglesFollowHeadRotation) {
    for (const HeadPose& p :
         {HeadPose{{}, 5.0, 0.0, 0.0}, HeadPose{{}, -5.0, 0.0, 0.0}, HeadPose{{}, 37.0, -21.5, 12.25},
          HeadPose{{}, 90.0, 90.0, 90.0}, HeadPose{{}, -170.0, 89.5, -45.0}}) {
        const dmat3 r = quaternion_rotation(angles_quaternion(p));
        EXPECT_TRUE(near_rotation(r, head_rotation(p), 2e-15)) << p.yaw_deg << " " << p.pitch_deg << " " << p.roll_deg;
        EXPECT_NEAR(glm::determinant(r), 1.0, 2e-15);
    }
}

TEST(Quaternions, OpenXrConvention) {
    // A quaternion (x, y, z, w) = (sin(a/2) · axis, cos(a/2)) turns by a
    // about the axis, right-handed: 90° about +Y maps -Z (forward) to -X.
    const double s = std::sqrt(0.5);
    const dmat3 r = quaternion_rotation(dvec4(0.0, s, 0.0, s));
    EXPECT_TRUE(near_vec(forward_of(r), dvec3(-1, 0, 0), 4e-16));
    EXPECT_TRUE(near_vec(r[0], dvec3(0, 0, -1), 4e-16));
    // A slightly long one is normalised first.
    const dmat3 long_r = quaternion_rotation(dvec4(0.0, s, 0.0, s) * (1.0 + 1e-7));
    EXPECT_TRUE(near_rotation(long_r, r, 4e-16));
}

}  // namespace
}  // namespace impossible::math
