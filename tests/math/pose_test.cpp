// Head pose conventions, eyes and view matrices.
#include <random>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/pose.hpp"
#include "math/rigid.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::kEps;
using testing::near_mat;
using testing::near_vec;

dvec3 right_of(const dmat3& r) { return r[0]; }
dvec3 up_of(const dmat3& r) { return r[1]; }

TEST(SinCosDeg, ExactAtMultiplesOf90) {
    EXPECT_EQ(sin_cos_deg(0.0), glm::dvec2(0.0, 1.0));
    EXPECT_EQ(sin_cos_deg(90.0), glm::dvec2(1.0, 0.0));
    EXPECT_EQ(sin_cos_deg(180.0), glm::dvec2(0.0, -1.0));
    EXPECT_EQ(sin_cos_deg(-90.0), glm::dvec2(-1.0, 0.0));
    EXPECT_EQ(sin_cos_deg(270.0), glm::dvec2(-1.0, 0.0));
    EXPECT_EQ(sin_cos_deg(-720.0 + 90.0), glm::dvec2(1.0, 0.0));
    EXPECT_EQ(sin_cos_deg(3600.0 * 7 + 180.0), glm::dvec2(0.0, -1.0));
}

TEST(SinCosDeg, MatchesStdAtOtherAngles) {
    for (double deg : {1.0, 30.0, 37.0, 123.456, -200.0, 359.0, 1e5 + 0.25}) {
        const glm::dvec2 sc = sin_cos_deg(deg);
        const double a = radians(deg);
        EXPECT_NEAR(sc.x, std::sin(a), 1e-12) << deg;
        EXPECT_NEAR(sc.y, std::cos(a), 1e-12) << deg;
        EXPECT_NEAR(sc.x * sc.x + sc.y * sc.y, 1.0, 4 * kEps) << deg;
    }
}

TEST(HeadRotation, IdentityLooksAlongMinusZ) {
    const dmat3 r = head_rotation(HeadPose{});
    EXPECT_EQ(forward_of(r), dvec3(0, 0, -1));
    EXPECT_EQ(right_of(r), dvec3(1, 0, 0));
    EXPECT_EQ(up_of(r), dvec3(0, 1, 0));
}

TEST(HeadRotation, Yaw90LooksAlongMinusX) {
    const dmat3 r = head_rotation(HeadPose{{}, 90.0, 0.0, 0.0});
    EXPECT_EQ(forward_of(r), dvec3(-1, 0, 0));  // turned left
    EXPECT_EQ(right_of(r), dvec3(0, 0, -1));
    EXPECT_EQ(up_of(r), dvec3(0, 1, 0));
    const dmat3 l = head_rotation(HeadPose{{}, -90.0, 0.0, 0.0});
    EXPECT_EQ(forward_of(l), dvec3(1, 0, 0));
}

TEST(HeadRotation, Pitch90LooksUp) {
    const dmat3 r = head_rotation(HeadPose{{}, 0.0, 90.0, 0.0});
    EXPECT_EQ(forward_of(r), dvec3(0, 1, 0));
    EXPECT_EQ(right_of(r), dvec3(1, 0, 0));  // pitch is about the right axis
    EXPECT_EQ(up_of(r), dvec3(0, 0, 1));
}

TEST(HeadRotation, PositiveRollLowersTheRightEye) {
    const dmat3 r = head_rotation(HeadPose{{}, 0.0, 0.0, 30.0});
    EXPECT_LT(right_of(r).y, 0.0);
    EXPECT_NEAR(right_of(r).y, -0.5, 1e-15);
    EXPECT_TRUE(near_vec(forward_of(r), dvec3(0, 0, -1), 0.0));  // roll keeps the view direction
    const auto eyes = eyes_of(HeadPose{{0, 1.6, 0}, 0.0, 0.0, 30.0}, 0.064);
    EXPECT_LT(eyes[1].position.y, eyes[0].position.y);
}

TEST(HeadRotation, OrderIsYawThenPitchThenRoll) {
    // Yaw 90 then pitch 90: the pitch turns about the *turned* right axis
    // (-Z), so the head looks up and its up vector points along +X, away
    // from where the face pointed before pitching (-X).
    const dmat3 r = head_rotation(HeadPose{{}, 90.0, 90.0, 0.0});
    EXPECT_TRUE(near_vec(forward_of(r), dvec3(0, 1, 0), 0.0));
    EXPECT_TRUE(near_vec(right_of(r), dvec3(0, 0, -1), 0.0));
    EXPECT_TRUE(near_vec(up_of(r), dvec3(1, 0, 0), 0.0));
    // Then roll 90 about the new forward (+Y, up): right-handed about +Y
    // turns the right axis (-Z) to -X.
    const dmat3 q = head_rotation(HeadPose{{}, 90.0, 90.0, 90.0});
    EXPECT_TRUE(near_vec(forward_of(q), dvec3(0, 1, 0), 0.0));
    EXPECT_TRUE(near_vec(right_of(q), dvec3(-1, 0, 0), 0.0));
}

TEST(HeadRotation, IsARotation) {
    const dmat3 r = head_rotation(HeadPose{{}, 37.0, -21.5, 12.25});
    dmat4 m(r);
    EXPECT_LT(orthonormality_error(m), 4 * kEps);
    EXPECT_NEAR(glm::determinant(r), 1.0, 4 * kEps);
}

TEST(Eyes, LeftFirstAtMinusHalfIpd) {
    const HeadPose pose{{1.0, 1.6, -2.0}, 90.0, 0.0, 0.0};
    const auto eyes = eyes_of(pose, 0.064);
    // Facing -X, the right is -Z: the left eye is at +Z.
    EXPECT_TRUE(near_vec(eyes[0].position, dvec3(1.0, 1.6, -2.0 + 0.032), 1e-15));
    EXPECT_TRUE(near_vec(eyes[1].position, dvec3(1.0, 1.6, -2.0 - 0.032), 1e-15));
    EXPECT_NEAR(glm::distance(eyes[0].position, eyes[1].position), 0.064, 1e-15);
    EXPECT_EQ(eyes[0].rotation, head_rotation(pose));
    EXPECT_EQ(eyes[1].rotation, head_rotation(pose));
}

TEST(ViewMatrix, InverseOfEyeToWorld) {
    const auto eyes = eyes_of(HeadPose{{3.25, 1.7, -7.5}, 37.0, 12.0, -5.0}, 0.07);
    for (const Eye& e : eyes) {
        EXPECT_TRUE(near_mat(view_matrix(e) * eye_to_world(e), dmat4(1.0), 8 * kEps));
        EXPECT_TRUE(near_mat(eye_to_world(e) * view_matrix(e), dmat4(1.0), 8 * 8 * kEps));
        // The eye sits at the origin of eye space and looks along -Z there.
        EXPECT_TRUE(near_vec(testing::apply(view_matrix(e), e.position), dvec3(0.0), 8 * 8 * kEps));
        const dvec3 ahead = e.position + 2.0 * forward_of(e.rotation);
        EXPECT_TRUE(near_vec(testing::apply(view_matrix(e), ahead), dvec3(0, 0, -2), 16 * 8 * kEps));
    }
}

TEST(TransformEye, MapsPositionAndAxes) {
    dmat4 m(head_rotation(HeadPose{{}, 90.0, 0.0, 0.0}));
    m[3] = dvec4(10.0, 0.0, 0.0, 1.0);
    const Eye e{{1.0, 2.0, 3.0}, dmat3(1.0)};
    const Eye t = transform_eye(m, e);
    // R_y(90): (x, y, z) → (z, y, -x), then +10 in x.
    EXPECT_TRUE(near_vec(t.position, dvec3(13.0, 2.0, -1.0), 0.0));
    EXPECT_TRUE(near_vec(forward_of(t.rotation), dvec3(-1, 0, 0), 0.0));
    EXPECT_TRUE(near_mat(view_matrix(t) * m, view_matrix(e), 32 * kEps));
}

TEST(HeadPoseFrom, InvertsHeadRotation) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> yaw(-179.0, 179.0), pitch(-89.0, 89.0), roll(-179.0, 179.0);
    for (int i = 0; i < 200; ++i) {
        const HeadPose p{{1.0, 2.0, 3.0}, yaw(rng), pitch(rng), roll(rng)};
        const HeadPose back = head_pose_from(p.position, head_rotation(p));
        EXPECT_NEAR(back.yaw_deg, p.yaw_deg, 1e-9);
        EXPECT_NEAR(back.pitch_deg, p.pitch_deg, 1e-9);
        EXPECT_NEAR(back.roll_deg, p.roll_deg, 1e-9);
    }
    // Straight down: the rotation is still reproduced (roll folded into yaw).
    const HeadPose down{{0.0, 0.0, 0.0}, 30.0, -90.0, 20.0};
    const dmat3 r = head_rotation(down);
    const dmat3 again = head_rotation(head_pose_from(down.position, r));
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(again[c][k], r[c][k], 1e-9);
}

TEST(HeadPoseFrom, ReadsBackAGridOfAngles) {
    for (double yaw : {-170.0, -30.0, 0.0, 45.0, 120.0})
        for (double pitch : {-60.0, 0.0, 20.0})
            for (double roll : {-45.0, 0.0, 10.0}) {
                const HeadPose pose{{1, 2, 3}, yaw, pitch, roll};
                const HeadPose back = head_pose_from(pose.position, head_rotation(pose));
                EXPECT_NEAR(back.yaw_deg, yaw, 1e-9);
                EXPECT_NEAR(back.pitch_deg, pitch, 1e-9);
                EXPECT_NEAR(back.roll_deg, roll, 1e-9);
            }
}

}  // namespace
}  // namespace impossible::math
