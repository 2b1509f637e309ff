// The VSM particle model (Frenning 2022, sections 2.4-3.4, Appendix C).
#include "vsm/vsm_model.hpp"

#include "core/errors.hpp"
#include "vsm/contact_energy.hpp"

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <sstream>

namespace softgrain::vsm {

namespace {

// Adds Pi x_c (x) beta / V to the linear map of F_a: block(3 i + j, m) += Pi(i, m) beta_j / V.
void add_term(std::vector<JacobianTerm>& terms, int c, const Mat3& Pi, const Vec3& beta, double volume)
{
    JacobianTerm* term = nullptr;
    for (auto& t : terms)
        if (t.particle == c) term = &t;
    if (!term) {
        terms.push_back({c, Block93::Zero()});
        term = &terms.back();
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            term->block.row(3 * i + j) += Pi.row(i) * (beta[j] / volume);
}

Eigen::Matrix<double, 9, 1> vec(const Mat3& M)
{
    Eigen::Matrix<double, 9, 1> v;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            v[3 * i + j] = M(i, j);
    return v;
}

} // namespace

Mat3 boundary_projection(BoundaryKind kind, const Vec3& normal)
{
    const Mat3 NN = normal * normal.transpose();
    switch (kind) {
    case BoundaryKind::free:
        return Mat3::Zero();
    case BoundaryKind::total:
        return Mat3::Identity();
    case BoundaryKind::symmetric:
        return NN;
    case BoundaryKind::antisymmetric:
        return Mat3::Identity() - NN;
    }
    return Mat3::Zero();
}

double Material::p_wave_speed() const
{
    const LameParameters m = lame();
    return std::sqrt((m.lambda + 2 * m.mu) / density);
}

double Material::shear_wave_speed() const
{
    return std::sqrt(lame().mu / density);
}

Model::Model(ReferenceCells cells, const Domain& domain, BoundaryConditions bc, Material material,
             ModelOptions options)
    : cells_(std::move(cells)), domain_(domain), bc_(std::move(bc)), material_(material), options_(options)
{
    const int n = static_cast<int>(cells_.size());
    mass_.resize(static_cast<std::size_t>(n));
    ghosts_.resize(static_cast<std::size_t>(n));
    K_prime_.resize(static_cast<std::size_t>(n));
    free_rows_.resize(static_cast<std::size_t>(n));
    stress_jacobian_.resize(static_cast<std::size_t>(n));
    full_jacobian_.resize(static_cast<std::size_t>(n));
    min_branch_ = std::numeric_limits<double>::infinity();
    const Mat3 I = Mat3::Identity();

    for (int a = 0; a < n; ++a) {
        const auto ua = static_cast<std::size_t>(a);
        const auto& list = cells_.neighbours[ua];
        const double V = cells_.volume[ua];
        mass_[ua] = material_.density * V;
        const int m = static_cast<int>(list.size());
        double shortest = std::numeric_limits<double>::infinity();
        for (const auto& nb : list)
            shortest = std::min(shortest, nb.length);
        min_branch_of_.push_back(shortest);
        min_branch_ = std::min(min_branch_, shortest);

        // Ghosts and their projections D_ab, eq. (14).
        free_rows_[ua].assign(static_cast<std::size_t>(m), -1);
        std::vector<int> rows; // E''_a: ghosts whose boundary point is not fully prescribed
        for (int k = 0; k < m; ++k) {
            const Neighbour& nb = list[static_cast<std::size_t>(k)];
            if (!nb.ghost()) continue;
            const int label = nb.label;
            if (label < 0 || label >= static_cast<int>(bc_.kind.size()))
                throw InputError("no boundary condition for face label " + std::to_string(label));
            const BoundaryKind kind = bc_.kind[static_cast<std::size_t>(label)];
            if (kind != BoundaryKind::free && !bc_.displacement)
                throw InputError(
                    "a displacement boundary condition needs a prescribed displacement function");
            ghosts_[ua].push_back({k, label, kind, boundary_projection(kind, nb.normal)});
            if (kind != BoundaryKind::total) {
                free_rows_[ua][static_cast<std::size_t>(k)] = static_cast<int>(rows.size());
                rows.push_back(k);
            }
        }

        // Least-squares ghost positions, eqs. (15)-(22): H_acd = X_ac . B_ad / V_a, eq. (16);
        // K_abc = delta_bc - (H_abc + H_acb) + sum_d H_adb H_adc, eq. (18); K'_a = -Kbar_a^-1 K_a over the
        // columns I'_a and E'_a (the E''_a columns of K' are zero).
        Eigen::MatrixXd Kp = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), m);
        if (!rows.empty()) {
            Eigen::MatrixXd H(m, m);
            for (int c = 0; c < m; ++c)
                for (int d = 0; d < m; ++d)
                    H(c, d) =
                        list[static_cast<std::size_t>(c)].branch.dot(list[static_cast<std::size_t>(d)].B_ab) /
                        V;
            const Eigen::MatrixXd K = Eigen::MatrixXd::Identity(m, m) - H - H.transpose() + H.transpose() * H;
            const auto r = static_cast<Eigen::Index>(rows.size());
            Eigen::MatrixXd Kbar(r, r), Krest = Eigen::MatrixXd::Zero(r, m);
            for (Eigen::Index i = 0; i < r; ++i) {
                for (Eigen::Index j = 0; j < r; ++j)
                    Kbar(i, j) = K(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]);
                for (int c = 0; c < m; ++c)
                    if (free_rows_[ua][static_cast<std::size_t>(c)] < 0)
                        Krest(i, c) = K(rows[static_cast<std::size_t>(i)], c);
            }
            Eigen::FullPivLU<Eigen::MatrixXd> lu(Kbar);
            if (lu.rank() < r)
                throw InputError(
                    "particle " + std::to_string(a) +
                    ": the least-squares ghost positions of eq. (21) are singular (Kbar not invertible)");
            Kp = -lu.solve(Krest);
        }
        K_prime_[ua] = Kp;

        // Linear maps of F_a = (1/V_a) sum_k x_ak (x) B_ak (eq. (6)) in the positions.
        auto& stress = stress_jacobian_[ua];
        auto& full = full_jacobian_[ua];
        for (int k = 0; k < m; ++k) {
            const Neighbour& nb = list[static_cast<std::size_t>(k)];
            if (nb.ghost()) continue;
            for (auto* terms : {&stress, &full}) {
                add_term(*terms, nb.particle, I, nb.B_ab, V);
                add_term(*terms, a, -I, nb.B_ab, V);
            }
        }
        for (const Ghost& g : ghosts_[ua]) {
            const Vec3& B = list[static_cast<std::size_t>(g.slot)].B_ab;
            // Prescribed part D xbar = 2 D (w - x_a): only in the full map (eqs. (66)-(67)).
            add_term(full, a, -2.0 * g.D, B, V);
            const int row = free_rows_[ua][static_cast<std::size_t>(g.slot)];
            if (row < 0) continue;
            const Mat3 free_part = I - g.D;
            // (I - D) x'_ab with, eq. (23),
            //   x'_ab = sum_{c in I'} K'_abc (x_c - x_a) + sum_{c in E'} K'_abc xbar_ac.
            for (int c = 0; c < m; ++c) {
                const double coefficient = Kp(row, c);
                if (coefficient == 0) continue;
                const Neighbour& nc = list[static_cast<std::size_t>(c)];
                if (!nc.ghost()) {
                    for (auto* terms : {&stress, &full}) {
                        add_term(*terms, nc.particle, coefficient * free_part, B, V);
                        add_term(*terms, a, -coefficient * free_part, B, V);
                    }
                } else {
                    // xbar_ac = 2 (w_ac - x_a), eq. (68)
                    add_term(full, a, -2.0 * coefficient * free_part, B, V);
                }
            }
        }
    }
}

Vec3 Model::prescribed_branch(const Points<3>& x, int a, const Neighbour& nb, int label, double t) const
{
    // xbar_ab = 2 (W_ab + ubar_ab - x_a), section 2.4.
    return 2.0 * (nb.boundary_point + bc_.displacement(label, nb.boundary_point, t) - x.col(a));
}

std::vector<Vec3> Model::ghost_branches(const Points<3>& x, int a, double t) const
{
    const auto ua = static_cast<std::size_t>(a);
    const auto& list = cells_.neighbours[ua];
    const std::size_t m = list.size();
    std::vector<Vec3> branch(m, Vec3::Zero()), prescribed(m, Vec3::Zero());
    for (const Ghost& g : ghosts_[ua])
        if (g.kind != BoundaryKind::free)
            prescribed[static_cast<std::size_t>(g.slot)] =
                prescribed_branch(x, a, list[static_cast<std::size_t>(g.slot)], g.label, t);
    for (const Ghost& g : ghosts_[ua]) {
        const auto k = static_cast<std::size_t>(g.slot);
        if (g.kind == BoundaryKind::total) {
            branch[k] = prescribed[k];
            continue;
        }
        // x'_ab, eq. (22), then x_ab = D xbar + (I - D) x', eq. (24).
        const int row = free_rows_[ua][k];
        Vec3 x_free = Vec3::Zero();
        for (std::size_t c = 0; c < m; ++c) {
            const double coefficient = K_prime_[ua](row, static_cast<Eigen::Index>(c));
            if (coefficient == 0) continue;
            const Vec3 x_ac = list[c].ghost() ? prescribed[c] : Vec3(x.col(list[c].particle) - x.col(a));
            x_free += coefficient * x_ac;
        }
        branch[k] = g.D * prescribed[k] + (Mat3::Identity() - g.D) * x_free;
    }
    return branch;
}

Mat3 Model::deformation_gradient(const Points<3>& x, int a, double t) const
{
    const auto ua = static_cast<std::size_t>(a);
    const auto& list = cells_.neighbours[ua];
    const std::vector<Vec3> ghost = ghost_branches(x, a, t);
    Mat3 F = Mat3::Zero();
    for (std::size_t k = 0; k < list.size(); ++k) {
        const Vec3 x_ab = list[k].ghost() ? ghost[k] : Vec3(x.col(list[k].particle) - x.col(a));
        F += x_ab * list[k].B_ab.transpose(); // eq. (6)
    }
    return F / cells_.volume[ua];
}

std::vector<Mat3> Model::deformation_gradients(const Points<3>& x, double t) const
{
    std::vector<Mat3> F(size());
#pragma omp parallel for schedule(static) if (size() > 4000) // threads pay off only for large sets
    for (int a = 0; a < static_cast<int>(size()); ++a)
        F[static_cast<std::size_t>(a)] = deformation_gradient(x, a, t);
    return F;
}

Mat3 Model::deformation_rate(const Points<3>& x, const Points<3>& v, int a, double t) const
{
    const auto ua = static_cast<std::size_t>(a);
    Mat3 rate = Mat3::Zero();
    for (const JacobianTerm& term : full_jacobian_[ua]) {
        const Eigen::Matrix<double, 9, 1> column = term.block * v.col(term.particle);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                rate(i, j) += column[3 * i + j];
    }
    bool prescribed = false;
    for (const Ghost& g : ghosts_[ua])
        prescribed = prescribed || g.kind != BoundaryKind::free;
    if (prescribed) {
        // F_a is affine in the prescribed displacements; their time derivative by a central difference.
        const double delta = 1e-6;
        rate += (deformation_gradient(x, a, t + delta) - deformation_gradient(x, a, t - delta)) / (2 * delta);
    }
    return rate;
}

Mat3 Model::viscous_stress(const Mat3& F, const Mat3& F_rate, int a) const
{
    const Mat3 F_inv = F.inverse();
    const Mat3 L = F_rate * F_inv;
    const Mat3 d = 0.5 * (L + L.transpose());
    const double h = min_branch_of_[static_cast<std::size_t>(a)];
    const Mat3 sigma =
        material_.density *
        (options_.c1 * material_.p_wave_speed() * h + options_.c2 * h * h * std::abs(d.trace())) * d;
    return F.determinant() * sigma * F_inv.transpose();
}

std::vector<double> Model::pressures(const Points<3>& x, double t) const
{
    const LameParameters lame = material_.lame();
    std::vector<double> p;
    for (const Mat3& F : deformation_gradients(x, t)) {
        p.push_back(-neo_hookean_cauchy_stress(F, lame).trace() / 3.0);
    }
    return p;
}

Points<3> Model::forces(const Points<3>& x, double t, long step, const Points<3>* v) const
{
    const int n = static_cast<int>(size());
    const LameParameters lame = material_.lame();
    const std::vector<Mat3> F = deformation_gradients(x, t);
    std::vector<Mat3> P(static_cast<std::size_t>(n));
    for (int a = 0; a < n; ++a) {
        const double J = F[static_cast<std::size_t>(a)].determinant();
        if (!(J > 0)) {
            std::ostringstream m;
            m << "J = det F_a = " << J << " <= 0 for particle " << a << " at t = " << t << " s";
            throw NumericalError(
                m.str(), step,
                "an inverted particle: distortion too large for the discretisation, time step "
                "above the stability limit, or missing stabilisation (xi = 0)");
        }
        P[static_cast<std::size_t>(a)] = neo_hookean_stress(F[static_cast<std::size_t>(a)], lame); // eq. (48)
        // Artificial viscosity, eq. (51).
        if (v && (options_.c1 > 0 || options_.c2 > 0))
            P[static_cast<std::size_t>(a)] +=
                viscous_stress(F[static_cast<std::size_t>(a)], deformation_rate(x, *v, a, t), a);
    }

    Points<3> f = Points<3>::Zero(3, n);
    for (int a = 0; a < n; ++a) {
        const auto ua = static_cast<std::size_t>(a);
        const auto& list = cells_.neighbours[ua];
        const Mat3& Pa = P[ua];
        if (options_.internal == InternalForce::eq43) {
            // f_c -= V_a (dF_a/dx_c)^T : P_a over the particles c of the map, eq. (43).
            const Eigen::Matrix<double, 9, 1> p = cells_.volume[ua] * vec(Pa);
            for (const JacobianTerm& term : stress_jacobian_[ua])
                f.col(term.particle) -= term.block.transpose() * p;
        } else {
            // f_a = sum_{b in I'_a} (P_a B_ab - P_b B_ba), eq. (42).
            for (const Neighbour& nb : list)
                if (!nb.ghost())
                    f.col(a) += Pa * nb.B_ab - P[static_cast<std::size_t>(nb.particle)] * nb.B_ba;
        }
        // Body force m_a g, eq. (39) (printed without m_a; the m_a follows from eq. (35)).
        if (options_.gravity != Vec3::Zero()) f.col(a) += mass_[ua] * options_.gravity;
        // Reactions D_ab P_a A_ab on displacement boundaries and prescribed tractions A_ab T_ab, eq. (39).
        for (const Ghost& g : ghosts_[ua]) {
            const Neighbour& nb = list[static_cast<std::size_t>(g.slot)];
            if (g.kind != BoundaryKind::free)
                f.col(a) += g.D * (Pa * (nb.area * nb.normal));
            else if (bc_.traction)
                f.col(a) += nb.area * bc_.traction(g.label, nb.boundary_point, t);
        }
    }
    if (options_.xi_n > 0 || options_.xi_t > 0) f += contact_forces(x, F, t);
    if (!bc_.plates.empty()) add_plate_forces(x, t, f);
    return f;
}

template <class OnTouch>
void Model::for_each_plate_contact(const Points<3>& x, double t, OnTouch&& on_touch) const
{
    for (int a = 0; a < static_cast<int>(size()); ++a) {
        const auto ua = static_cast<std::size_t>(a);
        std::vector<Vec3> branch;
        for (const Ghost& g : ghosts_[ua]) {
            if (g.kind != BoundaryKind::free) continue;
            for (std::size_t p = 0; p < bc_.plates.size(); ++p) {
                const RigidPlate& plate = bc_.plates[p];
                if (plate.label != g.label) continue;
                if (branch.empty()) branch = ghost_branches(x, a, t);
                const auto k = static_cast<std::size_t>(g.slot);
                const Vec3 w = x.col(a) + 0.5 * branch[k]; // w_ab = (x_a + x_b)/2
                const double gap = plate.normal.dot(w) - plate.height(t);
                if (gap <= 0) continue;
                const Neighbour& nb = cells_.neighbours[ua][k];
                on_touch(a, g, p, nb.area * plate.penalty * material_.young / nb.length, gap);
            }
        }
    }
}

void Model::add_plate_forces(const Points<3>& x, double t, Points<3>& f) const
{
    for_each_plate_contact(x, t, [&](int a, const Ghost& g, std::size_t p, double k, double gap) {
        // w_ab = x_a + x'_ab/2 with x'_ab = sum_{c in I'} K'_abc (x_c - x_a) + sum_{c in E'} K'_abc 2 (w_ac - x_a),
        // eq. (23): dw/dx_c = K'_abc/2 for a real neighbour c, dw/dx_a = 1 - sum K'/2 - sum_{E'} K'.
        const Vec3 push = -k * gap * bc_.plates[p].normal;
        const auto ua = static_cast<std::size_t>(a);
        const auto& list = cells_.neighbours[ua];
        const int row = free_rows_[ua][static_cast<std::size_t>(g.slot)];
        double own = 1;
        for (std::size_t c = 0; c < list.size(); ++c) {
            const double coefficient = K_prime_[ua](row, static_cast<Eigen::Index>(c));
            if (coefficient == 0) continue;
            if (list[c].ghost()) {
                own -= coefficient;
            } else {
                own -= 0.5 * coefficient;
                f.col(list[c].particle) += 0.5 * coefficient * push;
            }
        }
        f.col(a) += own * push;
    });
}

Model::PlateLoad Model::plate_load(const Points<3>& x, double t, std::size_t plate) const
{
    PlateLoad load;
    for_each_plate_contact(x, t, [&](int, const Ghost&, std::size_t p, double k, double gap) {
        if (p != plate) return;
        load.force += k * gap;
        ++load.contacts;
    });
    return load;
}

double Model::plate_energy(const Points<3>& x, double t) const
{
    double energy = 0;
    for_each_plate_contact(
        x, t, [&](int, const Ghost&, std::size_t, double k, double gap) { energy += 0.5 * k * gap * gap; });
    return energy;
}

template <class OnReal, class OnGhost>
void Model::for_each_contact(const Points<3>& x, const std::vector<Mat3>& F, double t, OnReal&& on_real,
                             OnGhost&& on_ghost) const
{
    const LameParameters lame = material_.lame();
    for (int a = 0; a < static_cast<int>(size()); ++a) {
        const auto ua = static_cast<std::size_t>(a);
        const auto& list = cells_.neighbours[ua];
        std::vector<Vec3> ghost;
        if (!ghosts_[ua].empty()) ghost = ghost_branches(x, a, t);
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Neighbour& nb = list[k];
            const ContactStiffness K =
                contact_stiffness(options_.xi_n, options_.xi_t, material_.young, lame.mu, nb.area, nb.length);
            if (!nb.ghost()) {
                const int b = nb.particle;
                if (b < a) continue; // each real pair once
                // u = x_ab - F_ab X_ab, F_ab = (F_a + F_b)/2, eq. (29).
                const Vec3 x_ab = x.col(b) - x.col(a);
                const Vec3 u = x_ab - 0.5 * (F[ua] + F[static_cast<std::size_t>(b)]) * nb.branch;
                on_real(a, b, K, u, x_ab, nb.branch);
            } else {
                const Ghost* g = nullptr;
                for (const Ghost& candidate : ghosts_[ua])
                    if (candidate.slot == static_cast<int>(k)) g = &candidate;
                if (g->kind == BoundaryKind::free) continue; // D = 0: no local displacement, eq. (30)
                // u = D (x_ab - F_a X_ab), eq. (30); n is the fixed boundary normal.
                on_ghost(a, *g, K, Vec3(g->D * (ghost[k] - F[ua] * nb.branch)), nb);
            }
        }
    }
}

Points<3> Model::contact_forces(const Points<3>& x, const std::vector<Mat3>& F, double t) const
{
    Points<3> f = Points<3>::Zero(3, static_cast<Eigen::Index>(size()));
    // y~ derivative: d(F_a X)/dx_c applied to g gives block^T vec(g X^T).
    const auto apply_y = [&](int a, const Vec3& g, const Vec3& X) {
        const Eigen::Matrix<double, 9, 1> gx = vec(g * X.transpose());
        for (const JacobianTerm& term : full_jacobian_[static_cast<std::size_t>(a)])
            f.col(term.particle) -= term.block.transpose() * gx;
    };
    for_each_contact(
        x, F, t,
        [&](int a, int b, const ContactStiffness& K, const Vec3& u, const Vec3& x_ab, const Vec3& X_ab) {
            const Vec3 gx = contact_gradient_x_real(u, x_ab, K);
            const Vec3 gy = contact_gradient_y(u, x_ab.normalized(), K);
            f.col(a) += gx; // dx_ab/dx_a = -I, eq. (65)
            f.col(b) -= gx;
            apply_y(a, 0.5 * gy, X_ab);
            apply_y(b, 0.5 * gy, X_ab);
        },
        [&](int a, const Ghost& g, const ContactStiffness& K, const Vec3& u, const Neighbour& nb) {
            const Vec3 gy = contact_gradient_y(u, nb.normal, K);
            f.col(a) -= 2.0 * (g.D * gy); // d(D x_ab)/dx_a = -2 D, eq. (66)-(67); dU/dx~ = -dU/dy~
            apply_y(a, g.D * gy, nb.branch);
        });
    return f;
}

double Model::internal_energy(const Points<3>& x, double t) const
{
    const LameParameters lame = material_.lame();
    double energy = 0;
    for (int a = 0; a < static_cast<int>(size()); ++a)
        energy += cells_.volume[static_cast<std::size_t>(a)] *
                  neo_hookean_energy(deformation_gradient(x, a, t), lame);
    return energy;
}

double Model::contact_energy_total(const Points<3>& x, double t) const
{
    double energy = 0;
    for_each_contact(
        x, deformation_gradients(x, t), t,
        [&](int, int, const ContactStiffness& K, const Vec3& u, const Vec3& x_ab, const Vec3&) {
            energy += contact_energy(u, x_ab.normalized(), K);
        },
        [&](int, const Ghost&, const ContactStiffness& K, const Vec3& u, const Neighbour& nb) {
            energy += contact_energy(u, nb.normal, K);
        });
    return energy;
}

} // namespace softgrain::vsm
