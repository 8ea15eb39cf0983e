// Rigid inverses and re-orthonormalisation.
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/pose.hpp"
#include "math/rigid.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::kEps;
using testing::near_mat;

dmat4 some_rigid() {
    dmat4 m(head_rotation(HeadPose{{}, 37.0, -12.0, 81.0}));
    m[3] = dvec4(3.14159, -2.71828, 1.41421, 1.0);
    return m;
}

TEST(RigidInverse, InvertsARigidTransform) {
    const dmat4 m = some_rigid();
    EXPECT_TRUE(near_mat(rigid_inverse(m) * m, dmat4(1.0), 16 * kEps));
    EXPECT_TRUE(near_mat(m * rigid_inverse(m), dmat4(1.0), 16 * kEps));
    EXPECT_TRUE(near_mat(rigid_inverse(m), glm::inverse(m), 16 * kEps));
}

TEST(OrthonormalizeRigid, RepairsADriftedRotationAndKeepsTheTranslation) {
    dmat4 m = some_rigid();
    m[0] *= 1.0 + 1e-7;
    m[1] += dvec4(2e-8, -1e-8, 3e-8, 0.0);
    m[2] *= 1.0 - 5e-8;
    m[0][3] = 1e-9;  // a last row that is not quite (0, 0, 0, 1)
    ASSERT_GT(orthonormality_error(m), 1e-8);
    const dmat4 o = orthonormalize_rigid(m);
    EXPECT_LT(orthonormality_error(o), 4 * kEps);
    EXPECT_NEAR(glm::determinant(dmat3(o)), 1.0, 4 * kEps);
    EXPECT_EQ(dvec3(o[3]), dvec3(m[3]));
    EXPECT_EQ(dvec4(o[0][3], o[1][3], o[2][3], o[3][3]), dvec4(0, 0, 0, 1));
    // Close to what it was: the change is of the size of the drift.
    EXPECT_LT(max_abs_difference(o, some_rigid()), 1e-6);
}

TEST(OrthonormalizeRigid, LeavesAnOrthonormalOneAlmostUnchanged) {
    const dmat4 m = some_rigid();
    EXPECT_TRUE(near_mat(orthonormalize_rigid(m), m, 4 * kEps));
    EXPECT_EQ(orthonormalize_rigid(dmat4(1.0)), dmat4(1.0));
}

TEST(OrthonormalityError, MeasuresTheDeviation) {
    EXPECT_EQ(orthonormality_error(dmat4(1.0)), 0.0);
    dmat4 m(1.0);
    m[1][1] = 1.5;
    EXPECT_DOUBLE_EQ(orthonormality_error(m), 1.25);
}

}  // namespace
}  // namespace impossible::math
