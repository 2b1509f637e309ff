// Linear-response shear modulus G = (1/V) [d^2U/dgamma^2 - Xi^T H^+ Xi] (linear_shear_modulus.hpp):
//   (a) against the analytic G of compressed triangular (2D) and fcc (3D) disk/sphere crystals
//       (shear_modulus.cpp, shear_modulus3d.cpp of this directory derive it). In the image-shift convention
//       the bonds across the y boundary make Xi and Xi^T H^+ Xi non-zero although the response is affine,
//       so the test checks that the two parts combine to the convention-free G;
//   (b) Xi against a central difference of the gradient with respect to gamma at fixed x;
//   (c) on small jammed packings, against the finite-strain G of Lees-Edwards steps (shear_modulus.hpp);
//   (d) on the same packings, the sparse pinned solve against the dense pseudo-inverse of H.
#include "dpm/analysis/linear_shear_modulus.hpp"
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/protocols/shear_modulus.hpp"
#include "support/packings.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::fcc_crystal;
using softgrain::verification::polished_packing2d;
using softgrain::verification::polished_packing3d;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// nx x ny disks (one-vertex particles, sigma = 1, k_c = 1) on a triangular lattice of spacing a.
DpmSystem triangular_crystal(double a, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.kc = 1.0;
    const int nx = 8, ny = 8;
    s.box = Eigen::Vector2d(nx * a, ny * a * std::sqrt(3.0) / 2);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            Eigen::Matrix2Xd c(2, 1);
            c << (i + 0.5 * (j % 2)) * a, j * a * std::sqrt(3.0) / 2;
            s.add_particle(c, 1.0, ShapeParameters{}, x);
        }
    return s;
}

StrainDerivatives strain_derivatives(const DpmSystem& s, const Eigen::VectorXd& x,
                                     Eigen::SparseMatrix<double>& h)
{
    StrainDerivatives strain;
    strain.x = &x;
    strain.mixed = Eigen::VectorXd::Zero(x.size());
    h = sparse_dynamical_matrix(s, x, &strain);
    return strain;
}

// Reference: Xi^T H^+ Xi / V from the dense eigendecomposition of H, leaving out the eigenvalues within
// +- pseudo_inverse_cut lambda_max (as the sparse solve).
double dense_relaxation(const Eigen::SparseMatrix<double>& h, const Eigen::VectorXd& xi, double volume)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(h)};
    const Eigen::VectorXd& lambda = solver.eigenvalues();
    const double cut = pseudo_inverse_cut * lambda.cwiseAbs().maxCoeff();
    const Eigen::VectorXd projected = solver.eigenvectors().transpose() * xi;
    double relaxation = 0;
    for (Eigen::Index k = 0; k < lambda.size(); ++k)
        if (std::abs(lambda(k)) > cut) relaxation += projected(k) * projected(k) / lambda(k);
    return relaxation / volume;
}

// The smallest |sigma - r| over the candidate vertex pairs of a rough packing: how far a separation can move
// before a contact of eq. (9.4) opens or closes.
double closest_contact_switch(const DpmSystem& s, const Eigen::VectorXd& x)
{
    double closest = s.box->maxCoeff();
    for (const VertexPair& pair : s.contacts.list(s, x)->pairs()) {
        const double distance =
            (x.segment<2>(2 * pair.neighbour.j) + pair.neighbour.shift - x.segment<2>(2 * pair.i)).norm();
        closest = std::min(closest, std::abs(pair.neighbour.sigma - distance));
    }
    return closest;
}

// The largest gradient components of the shape and of the contact terms alone, the scales of the
// round-off of sums of these forces.
struct ForceParts
{
    Eigen::VectorXd shape, contact;
};
ForceParts force_parts(const DpmSystem& s, const Eigen::VectorXd& x)
{
    ForceParts parts{Eigen::VectorXd::Zero(x.size()), Eigen::VectorXd::Zero(x.size())};
    total_energy(s, x, &parts.shape, nullptr, shape_part);
    total_energy(s, x, &parts.contact, nullptr, interaction_part);
    return parts;
}

// What the checks of a jammed packing need in either dimension.
struct PackingUnderTest
{
    double unit = 1;   // the model's pressure unit
    double volume = 0; // V
    int dimension = 2;
    Eigen::SparseMatrix<double> hessian;
    StrainDerivatives strain;
    ForceParts parts;
};

// (c) and (d) on one packing at its polished equilibrium x; `finite(dgamma)` is the finite-strain result.
template <class Finite>
void check_against_references(const LinearShearModulus& g, const PackingUnderTest& p,
                              const Eigen::VectorXd& x, const Finite& finite_strain)
{
    const double unit = p.unit;
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(p.hessian), Eigen::EigenvaluesOnly)
            .eigenvalues();
    const double lowest_nonzero = lambda(g.negative_modes + g.zero_modes);
    const double condition = g.largest_eigenvalue / lowest_nonzero;
    MESSAGE("G " << g.modulus / unit << " = " << g.affine / unit << " - " << g.relaxation / unit
                 << " [pressure unit]; zero modes " << g.zero_modes << ", negative " << g.negative_modes
                 << ", lambda " << lowest_nonzero << " ... " << g.largest_eigenvalue << ", zero-mode load "
                 << g.zero_mode_load << ", residual " << g.residual);
    CHECK(g.negative_modes == 0);
    CHECK(g.zero_modes >= p.dimension);
    // The inertia count against the dense spectrum: the zero modes end below the cut, the rest above.
    CHECK(std::abs(lambda(g.zero_modes - 1)) <= pseudo_inverse_cut * g.largest_eigenvalue);
    CHECK(lowest_nonzero > pseudo_inverse_cut * g.largest_eigenvalue);
    // (d) The dense reference: each eigenpair within n eps lambda_max (backward-stable solver), so a term
    // xi^2/lambda within n eps kappa relatively, kappa = lambda_max / lambda_min; the sparse LDL^T of the
    // pinned matrix (definite, backward stable) the same order. 4 n eps kappa.
    const double n = static_cast<double>(x.size());
    const double dense = dense_relaxation(p.hessian, p.strain.mixed, p.volume);
    MESSAGE("relaxation: sparse " << g.relaxation << ", dense " << dense << ", relative difference "
                                  << std::abs(g.relaxation - dense) / dense << ", 4 n eps kappa "
                                  << 4 * n * round_off * condition);
    CHECK_CLOSE(g.relaxation, dense, (Tolerance{4 * n * round_off * condition, 0}));
    CHECK(g.residual < 4 * n * round_off * condition);
    // (c) Finite strain: the least-squares slope over the stresses at 0, dgamma, 2 dgamma deviates from
    // dSigma/dgamma at 0 by Sigma'' dgamma, measured by the second difference of the three stresses,
    // |Sigma_2 - 2 Sigma_1 + Sigma_0| / dgamma (which also carries their noise). The noise: the stress sums
    // moments x_v F_v^T of the shape and contact forces (eq. 9.26), each rounded to eps of
    // S = sum_v |x_v| (|F_v^shape| + |F_v^contact|) / V; the Newton residual (forces <= 1e-13 of the
    // pressure unit) is far below those forces. 4 n eps S / dgamma for the slope.
    const auto points = x.reshaped(p.dimension, x.size() / p.dimension).colwise().norm().transpose();
    const auto shape =
        p.parts.shape.reshaped(p.dimension, x.size() / p.dimension).colwise().norm().transpose();
    const auto contact =
        p.parts.contact.reshaped(p.dimension, x.size() / p.dimension).colwise().norm().transpose();
    const double moment_scale = (points.array() * (shape + contact).array()).sum() / p.volume;
    for (double dgamma : {5e-9, 5e-10}) {
        const ShearModulusResult finite = finite_strain(dgamma);
        const std::vector<double>& stress = finite.shear_stress;
        const double curvature = std::abs(stress[2] - 2 * stress[1] + stress[0]) / dgamma;
        const double bound = curvature + 4 * n * round_off * moment_scale / dgamma;
        MESSAGE("dgamma " << dgamma << ": finite-strain G " << finite.modulus / unit << ", linear "
                          << g.modulus / unit << ", difference " << (finite.modulus - g.modulus) / unit
                          << ", curvature " << curvature / unit << ", bound " << bound / unit);
        CHECK(std::abs(finite.modulus - g.modulus) <= bound);
    }
}

} // namespace

TEST_CASE("linear-response G = sqrt(3)/4 k_c - 3/4 P for a compressed triangular disk crystal and "
          "k_c/(sqrt(2) a) - 3/4 P for an fcc sphere crystal [DPM sec. 9.4.3, eq. (9.4)]")
{
    // Round-off: G is a sum of O(n) terms of size k_c and a solve with the sparse LDL^T of H (condition
    // lambda_max / lambda_min ~ (L / a)^2 ~ 1e2 on the lowest phonon): relative errors ~ 1e2 n eps ~ 1e-11.
    // 1e-10 relative.
    for (double a : {0.999, 0.98}) {
        CAPTURE(a);
        Eigen::VectorXd x;
        const DpmSystem s = triangular_crystal(a, x);
        const double p = pressure(stress_tensor(s, x));
        const LinearShearModulus g = linear_shear_modulus(s, x);
        MESSAGE("2D a = " << a << ": G " << g.modulus << " = affine " << g.affine << " - relaxation "
                          << g.relaxation << "; zero modes " << g.zero_modes << ", residual " << g.residual);
        CHECK(g.zero_modes == 2); // the translations
        CHECK(g.negative_modes == 0);
        CHECK(g.relaxation > 1e-3 * g.affine); // image-shift convention: Xi != 0 on boundary bonds
        CHECK_CLOSE(g.modulus, std::sqrt(3.0) / 4 - 0.75 * p, (Tolerance{1e-10, 0}));
        CHECK(std::abs(g.stress) < 1e-12 * p); // -Sigma_xy of the unsheared crystal
    }
    for (double a : {0.999, 0.98}) {
        CAPTURE(a);
        Eigen::VectorXd x;
        const DpmSystem3d s = fcc_crystal(a, 3, x);
        const double p = pressure3d(stress_tensor3d(s, x));
        const LinearShearModulus g = linear_shear_modulus(s, x);
        MESSAGE("3D a = " << a << ": G " << g.modulus << " = affine " << g.affine << " - relaxation "
                          << g.relaxation << "; zero modes " << g.zero_modes);
        CHECK(g.zero_modes == 3);
        CHECK(g.negative_modes == 0);
        CHECK_CLOSE(g.modulus, s.kc / (std::sqrt(2.0) * a) - 0.75 * p, (Tolerance{1e-10, 0}));
    }
}

TEST_CASE(
    "Xi = d^2U/dx dgamma and d^2U/dgamma^2 against central differences in gamma at fixed x, on a jammed "
    "packing [DPM sec. 9.4.3]")
{
    const JamResult r = polished_packing2d(JamModel::surface_tension, 16, 1);
    const DpmSystem& s = r.system;
    Eigen::SparseMatrix<double> h;
    const StrainDerivatives strain = strain_derivatives(s, r.x, h);
    const double L = s.box->maxCoeff();
    // The step must not switch a contact (Theta(sigma - r) of eq. 9.4): a pair's separation moves by at most
    // step L (one image in y), so step L stays half the smallest |sigma - r| of the candidate pairs.
    const double closest_switch = closest_contact_switch(s, r.x);
    const double step = 0.5 * closest_switch / L;
    const auto at_strain = [&](double gamma, Eigen::VectorXd& gradient) {
        DpmSystem sheared = s;
        sheared.lees_edwards_strain = gamma;
        gradient = Eigen::VectorXd::Zero(r.x.size());
        StrainDerivatives d;
        d.x = &r.x;
        d.mixed = Eigen::VectorXd::Zero(r.x.size());
        total_energy(sheared, r.x, &gradient, HessianSink(nullptr, &d));
        return d.first;
    };
    Eigen::VectorXd plus, minus;
    const double first_plus = at_strain(step, plus), first_minus = at_strain(-step, minus);
    const Eigen::VectorXd difference = (plus - minus) / (2 * step);
    // Truncation: h^2/6 |d^3 g/dgamma^3|; each gamma-derivative of a spring's force brings a factor
    // L/r (r >= sigma_min/2 ~ 0.3 at these overlaps), so the error is below (2 h L/r)^2 |Xi|. Round-off: the
    // gradient vector sums the shape terms first (bit-identical at +-h: they do not depend on gamma), then
    // the contact terms, each addition rounding to eps of the partial sum, at most max|grad U_shape| +
    // max|grad U_contact|; and each contact term is evaluated at image coordinates x_j + s_j rounded to
    // eps |x_j + s_j| <= 2 eps L, which moves its force by up to k 2 eps L <= lambda_max 2 eps L. A few
    // contact terms per coordinate: 16 eps (max|grad U_shape| + max|grad U_contact| + 2 L lambda_max) / h.
    const ForceParts parts = force_parts(s, r.x);
    const double contact_scale = parts.contact.cwiseAbs().maxCoeff();
    const double stiffness_scale = 2 * L * largest_eigenvalue(h);
    const double force_scale = parts.shape.cwiseAbs().maxCoeff() + contact_scale + stiffness_scale;
    const double truncation = std::pow(2 * step * L / 0.3, 2) * strain.mixed.cwiseAbs().maxCoeff();
    const double rounding = 16 * round_off * force_scale / step;
    const double error = (difference - strain.mixed).cwiseAbs().maxCoeff();
    MESSAGE("step " << step << " (closest switch " << closest_switch << ", L " << L << "): max|Xi| "
                    << strain.mixed.cwiseAbs().maxCoeff() << ", max|FD - Xi| " << error << ", bound "
                    << truncation + rounding);
    CHECK(strain.mixed.cwiseAbs().maxCoeff() > 0);
    CHECK(error <= truncation + rounding);
    // d^2U/dgamma^2 against the difference of dU/dgamma = sum over the image terms of grad . (s_y e_x): the
    // same truncation; the round-off of that sum, n eps (max|grad U_contact| + 2 L lambda_max) L, over h.
    const double second = (first_plus - first_minus) / (2 * step);
    const double second_bound =
        std::pow(2 * step * L / 0.3, 2) * std::abs(strain.second) +
        static_cast<double>(r.x.size()) * round_off * (contact_scale + stiffness_scale) * L / step;
    MESSAGE("d2U/dgamma2 " << strain.second << ", difference of dU/dgamma " << second << ", bound "
                           << second_bound);
    CHECK(std::abs(second - strain.second) <= second_bound);
    // dU/dgamma = -V Sigma_xy (eq. 9.26): the virial at the polished equilibrium, to its round-off.
    const Eigen::Matrix2d sigma = stress_tensor(s, r.x);
    CHECK_CLOSE(strain.first / s.box->prod(), -sigma(1, 0), (Tolerance{1e-8, 1e-12 * r.pressure_unit}));
}

TEST_CASE("linear-response G of jammed 2D packings against the finite-strain G of Lees-Edwards steps and "
          "against a dense pseudo-inverse [DPM sec. 9.4.3]")
{
    for (const JamModel model : {JamModel::surface_tension, JamModel::shell}) {
        CAPTURE(jam_model_name(model));
        const JamResult r = polished_packing2d(model, 16, 2);
        const DpmSystem& s = r.system;
        PackingUnderTest p;
        p.unit = r.pressure_unit;
        p.volume = s.box->prod();
        p.dimension = 2;
        p.strain = strain_derivatives(s, r.x, p.hessian);
        p.parts = force_parts(s, r.x);
        check_against_references(linear_shear_modulus(s, r.x), p, r.x, [&](double dgamma) {
            return shear_modulus(s, r.x, dgamma, 2, 1e-13 * p.unit);
        });
    }
}

TEST_CASE("linear-response G of a jammed 3D shell packing against the finite-strain G and a dense "
          "pseudo-inverse [DPM sec. 9.4.3, Fig. 9.16b]")
{
    const Jam3dResult j =
        polished_packing3d(8, 1); // seed 3's packing has no contact across the y boundary: G = 0
    const DpmSystem3d& s = j.system;
    PackingUnderTest p;
    p.unit = j.pressure_unit;
    p.volume = std::pow(*s.box, 3);
    p.dimension = 3;
    p.strain.x = &j.x;
    p.strain.mixed = Eigen::VectorXd::Zero(j.x.size());
    p.hessian = sparse_dynamical_matrix3d(s, j.x, &p.strain);
    p.parts = {Eigen::VectorXd::Zero(j.x.size()), Eigen::VectorXd::Zero(j.x.size())};
    total_energy3d(s, j.x, &p.parts.shape, nullptr);
    interaction_energy3d(s, j.x, &p.parts.contact, nullptr);
    p.parts.shape -= p.parts.contact; // the shape part: total minus contacts
    const LinearShearModulus g = linear_shear_modulus(s, j.x);
    CHECK(p.strain.mixed.norm() > 0);
    // sigma_xy = (1/V) dU/dgamma = -Sigma_xy of the virial (3D eq. 9.26) at the polished equilibrium.
    CHECK_CLOSE(g.stress, -stress_tensor3d(s, j.x)(1, 0), (Tolerance{1e-8, 1e-12 * p.unit}));
    check_against_references(g, p, j.x,
                             [&](double dgamma) { return shear_modulus(s, j.x, dgamma, 2, 1e-13 * p.unit); });
}
