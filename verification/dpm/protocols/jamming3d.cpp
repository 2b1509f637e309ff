// ctest-label: slow
// DPM section 9.4 in 3D: the stress tensor of a periodic packing (the 3D analogue of eq. 9.26) gives the
// pressure P = Tr(Sigma)/3 = -dU/dV under a homogeneous dilation of every coordinate and the box (finite
// differences), on a deformed, overlapping packing with shape and contact forces; and the jamming protocol
// (compression, FIRE, bisection) ends in force balance at 1 <= P/P_t < 1.01 with contacts, where the
// dynamical matrix (eq. 9.28) of a shell packing has exactly the 3 zero modes of the periodic translations
// plus 6 per rattler (sec. 9.4.3, Fig. 9.15b).
#include "core/rng.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "support/jammed3d.hpp"
#include "support/tolerance.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_jammed3d;
using softgrain::verification::icosahedron_shape3d;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// Four randomly deformed icosahedral particles of the model (circumradius 1, k_v = 1, Stiffness3d's k's,
// floppy A0 = 1.15 > A_mesh = 1.098) overlapping in a periodic box of side 3.5, also across its faces.
DpmSystem3d deformed_overlapping(ShapeModel model, Eigen::VectorXd& x)
{
    DpmSystem3d s;
    s.box = 3.5;
    s.meshes.push_back(icosahedron_mesh());
    const ShapeParameters3d shape = icosahedron_shape3d(model, s.meshes[0]);
    Rng rng(11);
    for (int m = 0; m < 4; ++m) {
        const Eigen::Vector3d centre(0.3 + 1.75 * (m % 2), 0.2 + 1.75 * (m / 2), 1.75 + 0.4 * m);
        Eigen::Matrix3Xd v = s.meshes[0].vertices.colwise() + centre;
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.08 * rng.uniform(-1, 1);
        s.add_particle(0, v, 0.7, shape, x);
    }
    return s;
}

double dilated_energy(DpmSystem3d s, const Eigen::VectorXd& x, double f, bool contacts_only)
{
    *s.box *= f;
    return contacts_only ? interaction_energy3d(s, f * x, nullptr, nullptr)
                         : total_energy3d(s, f * x, nullptr, nullptr);
}

} // namespace

TEST_CASE("3D virial pressure = -dU/dV under homogeneous dilation [DPM eq. (9.26) in 3D]")
{
    for (ShapeModel model : {ShapeModel::shell, ShapeModel::floppy, ShapeModel::surface_tension}) {
        CAPTURE(static_cast<int>(model));
        Eigen::VectorXd x;
        const DpmSystem3d s = deformed_overlapping(model, x);
        const double V = std::pow(*s.box, 3);
        const double e = 1e-5; // relative dilation of every coordinate and the box
        const double dV = (std::pow(1 + e, 3) - std::pow(1 - e, 3)) * V;
        Eigen::Matrix3d contacts = Eigen::Matrix3d::Zero();
        interaction_energy3d(s, x, nullptr, nullptr, &contacts);
        CHECK(contacts.trace() > 0); // the particles do overlap: not vacuous
        // Central differences with e = 1e-5: truncation ~e^2 = 1e-10 relative, round-off ~eps U/(e P V)
        // ~1e-10; 1e-7 leaves a margin of 1000.
        const double P = pressure3d(stress_tensor3d(s, x));
        CHECK_CLOSE(P, -(dilated_energy(s, x, 1 + e, false) - dilated_energy(s, x, 1 - e, false)) / dV,
                    (Tolerance{1e-7, 0}));
        // The contact part alone obeys the same identity.
        CHECK_CLOSE(contacts.trace() / (3 * V),
                    -(dilated_energy(s, x, 1 + e, true) - dilated_energy(s, x, 1 - e, true)) / dV,
                    (Tolerance{1e-7, 0}));
    }
}

TEST_CASE(
    "3D jamming ends in force balance at 1 <= P/P_t < 1.01 with every particle in contact [DPM sec. 9.4]")
{
    Jam3dOptions o; // four icosahedral shells jammed at P_t = 1e-5 k_v v0 (seconds)
    o.particles = 4;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-5;
    o.seed = 3;
    Jam3dResult j = jam3d(o);
    const auto modes = check_jammed3d(j, o.pressure_onset);
    CHECK(modes.zero_modes == 3 + 6 * modes.rattlers);
}

// fire_step sets FIRE's largest step, dt_max = fire_step / sqrt(lambda_max at the start) (below the cap
// 0.5), and a packing jammed with three times the default step ends jammed all the same (force balance at
// 1 <= P/P_t < 1.01, no negative mode, 3 zero modes plus 6 per rattler). The ratio of the two steps is a
// quotient of the same square root: exact to 2 eps.
TEST_CASE("3D jamming with fire_step = 0.9: three times FIRE's default step, and a jammed packing")
{
    Jam3dOptions o;
    o.particles = 4;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-5;
    o.seed = 3;
    const Jam3dResult reference = jam3d(o);
    o.fire_step = 0.9;
    Jam3dResult j = jam3d(o);
    REQUIRE(j.fire.dt_max < 0.5);
    CHECK_CLOSE(j.fire.dt_max, 3 * reference.fire.dt_max, (Tolerance{2 * round_off, 0}));
    MESSAGE("FIRE iterations " << j.fire_iterations << " against " << reference.fire_iterations
                               << " with the default step");
    const auto modes = check_jammed3d(j, o.pressure_onset);
    CHECK(modes.zero_modes == 3 + 6 * modes.rattlers);
}
