#include "spd/tissue.hpp"
#include "core/step_count.hpp"

#include "core/checkpoint.hpp"

#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "spd/assembly.hpp"
#include "spd/time_step_limits.hpp"

#include <voro++.hh>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace softgrain::spd {

namespace {

// The mid-plane section of a voro++ cell of a slab: its face on the upper slab wall (voro++ wall id -6), as a
// CCW polygon in absolute coordinates.
std::vector<Vec2> slab_section(voro::voronoicell_neighbor& cell, const Vec2& centre)
{
    std::vector<int> neighbours, face_loop;
    std::vector<double> vertices;
    cell.neighbors(neighbours);
    cell.face_vertices(face_loop);
    cell.vertices(vertices); // relative to the particle
    std::vector<Vec2> polygon;
    std::size_t cursor = 0;
    for (int neighbour : neighbours) {
        const int count = face_loop[cursor];
        if (neighbour == -6)
            for (int k = 0; k < count; ++k) {
                const int v = face_loop[cursor + 1 + static_cast<std::size_t>(k)];
                polygon.push_back(centre + Vec2(vertices[3 * v], vertices[3 * v + 1]));
            }
        cursor += static_cast<std::size_t>(count) + 1;
    }
    Points<2> P(2, polygon.size());
    for (std::size_t k = 0; k < polygon.size(); ++k)
        P.col(static_cast<Eigen::Index>(k)) = polygon[k];
    if (polygon_signed_area(P) < 0) std::reverse(polygon.begin(), polygon.end());
    return polygon;
}

// Which sides of the box a point lies on (bit 0 left, 1 right, 2 bottom, 3 top), within `tolerance`.
int box_sides(const Vec2& x, double width, double height, double tolerance)
{
    return (std::abs(x.x()) < tolerance ? 1 : 0) | (std::abs(x.x() - width) < tolerance ? 2 : 0) |
           (std::abs(x.y()) < tolerance ? 4 : 0) | (std::abs(x.y() - height) < tolerance ? 8 : 0);
}

// Union-find root with path halving.
int root(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

// Groups of points closer than `distance` to one another (transitively): the group root of each point
// (union-find over the points sorted by x, so that only neighbours within `distance` in x are compared).
std::vector<int> proximity_groups(const std::vector<Vec2>& points, double distance)
{
    const int m = static_cast<int>(points.size());
    std::vector<int> parent(static_cast<std::size_t>(m));
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<int> order(parent);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return points[a].x() < points[b].x(); });
    for (int u = 0; u < m; ++u)
        for (int w = u + 1; w < m && points[order[w]].x() - points[order[u]].x() < distance; ++w)
            if ((points[order[w]] - points[order[u]]).norm() < distance)
                parent[root(parent, order[w])] = root(parent, order[u]);
    for (int u = 0; u < m; ++u)
        parent[u] = root(parent, u);
    return parent;
}

int distinct(std::vector<int> labels)
{
    std::sort(labels.begin(), labels.end());
    return static_cast<int>(std::unique(labels.begin(), labels.end()) - labels.begin());
}

// Inward unit normal of the edge a -> b of a CCW polygon.
Vec2 inward_normal(const Vec2& a, const Vec2& b)
{
    const Vec2 e = (b - a).normalized();
    return {-e.y(), e.x()};
}
} // namespace

Tessellation laguerre_tessellation(const TissueSetup& setup)
{
    Tessellation t;
    const double R = setup.radius;
    const double row_pitch = std::sqrt(3.0) * R;
    t.width = 2 * R * setup.columns;
    t.height = row_pitch * setup.rows;
    AssemblySetup disks; // the radii as for the ring assemblies (decision spd-polydispersity)
    disks.particles = setup.columns * setup.rows;
    disks.ring.radius = R;
    disks.radius_spread = setup.radius_spread;
    disks.seed = setup.seed;
    t.radii = ring_radii(disks);
    // Triangular lattice: even rows at x = (i + 1/2) 2R, odd rows shifted by R (their last disk on x = W is
    // dropped).
    std::vector<double> radii;
    for (int j = 0, p = 0; j < setup.rows; ++j)
        for (int i = 0; i < setup.columns; ++i, ++p) {
            const double x = (i + 0.5 + 0.5 * (j % 2)) * 2 * R;
            if (x >= t.width - 1e-9 * R) continue;
            t.centres.emplace_back(x, (j + 0.5) * row_pitch);
            radii.push_back(t.radii[static_cast<std::size_t>(p)]);
        }
    t.radii = radii;
    const int n = static_cast<int>(t.centres.size());
    const double slab = 0.5 * R;
    const auto blocks = [&](double size) { return std::max(1, static_cast<int>(size / (2 * R))); };
    voro::container_poly container(0, t.width, 0, t.height, -slab, slab, blocks(t.width), blocks(t.height), 1,
                                   false, false, false, 8);
    for (int i = 0; i < n; ++i)
        container.put(i, t.centres[i].x(), t.centres[i].y(), 0.0, t.radii[i]);
    std::vector<std::vector<Vec2>> polygons(static_cast<std::size_t>(n));
    voro::c_loop_all loop(container);
    voro::voronoicell_neighbor cell;
    if (loop.start()) do {
            if (!container.compute_cell(cell, loop)) continue;
            const int id = loop.pid();
            polygons[static_cast<std::size_t>(id)] = slab_section(cell, t.centres[id]);
            t.voronoi_area += cell.volume() / (2 * slab);
        } while (loop.inc());
    for (int i = 0; i < n; ++i)
        if (polygons[static_cast<std::size_t>(i)].size() < 3)
            throw NumericalError("Laguerre tessellation", 0,
                                 "voro++ returned no cell for disk " + std::to_string(i));

    // Shared corners: the copies of one corner in its cells coincide to round-off; corners closer than
    // 0.2 R are merged as well (decision spd-tissue-tessellation), onto the member on most box sides.
    std::vector<Vec2> all;
    for (const auto& polygon : polygons)
        all.insert(all.end(), polygon.begin(), polygon.end());
    const int m = static_cast<int>(all.size());
    const double on_side = 1e-9 * R;
    const std::vector<int> group = proximity_groups(all, 0.2 * R);
    std::map<int, int> corner_of_root;
    std::vector<int> corner_of(static_cast<std::size_t>(m));
    std::vector<int> best_sides, members;
    std::vector<Vec2> sum;
    for (int u = 0; u < m; ++u) {
        auto [it, fresh] = corner_of_root.try_emplace(group[u], static_cast<int>(sum.size()));
        if (fresh) {
            sum.emplace_back(0, 0);
            best_sides.push_back(-1);
            members.push_back(0);
        }
        const int c = it->second;
        corner_of[u] = c;
        const int sides = std::popcount(static_cast<unsigned>(box_sides(all[u], t.width, t.height, on_side)));
        if (sides > best_sides[c]) { // the position of the member on most box sides (mean of equals)
            best_sides[c] = sides;
            sum[c].setZero();
            members[c] = 0;
        }
        if (sides == best_sides[c]) {
            sum[c] += all[u];
            ++members[c];
        }
    }
    for (std::size_t c = 0; c < sum.size(); ++c)
        t.corners.push_back(sum[c] / members[c]);
    int u = 0;
    for (const auto& polygon : polygons) {
        std::vector<int> corners;
        for (std::size_t k = 0; k < polygon.size(); ++k, ++u)
            if (corners.empty() || corners.back() != corner_of[u]) corners.push_back(corner_of[u]);
        while (corners.size() > 1 && corners.front() == corners.back())
            corners.pop_back();
        if (corners.size() < 3)
            throw InputError("radius_spread = " + std::to_string(setup.radius_spread) +
                             ": a Laguerre cell collapsed below three corners after merging corners closer "
                             "than 0.2 R; allowed: a smaller spread");
        t.cells.push_back(corners);
    }
    // Corners of the exact tessellation (copies equal within round-off) that the 0.2 R merge removed.
    t.merged_corners = distinct(proximity_groups(all, on_side)) - static_cast<int>(t.corners.size());
    return t;
}

double total_cell_area(const Tessellation& t)
{
    double area = 0;
    for (const auto& corners : t.cells) {
        Points<2> P(2, corners.size());
        for (std::size_t k = 0; k < corners.size(); ++k)
            P.col(static_cast<Eigen::Index>(k)) = t.corners[corners[k]];
        area += polygon_signed_area(P);
    }
    return area;
}

TissueScales tissue_scales(const TissueSetup& setup)
{
    TissueScales sc;
    sc.l0 = 2 * setup.radius / std::sqrt(3.0) / setup.edge_segments;
    sc.laws = calibrate(setup.material, sc.l0);
    sc.F_star = sc.laws.k_b / setup.radius;
    sc.M_star = sc.F_star * sc.l0;
    sc.laws.M_Y = setup.plastic_ratio * sc.M_star;
    sc.laws.F_Y = INFINITY; // decision spd-ring-plasticity
    sc.link.k_n = setup.link_stiffness * sc.laws.k_s;
    sc.link.k_t = setup.shear_stiffness_ratio * sc.link.k_n;
    sc.link.f_n0 = -setup.cohesion * sc.F_star;
    sc.link.f_t0 = setup.shear_strength_ratio * setup.cohesion * sc.F_star;
    sc.link.alpha = 2;
    sc.W0 = sc.link.f_n0 * sc.link.f_n0 / (2 * sc.link.k_n);
    return sc;
}

Tissue build_tissue(const TissueSetup& setup)
{
    Tissue tissue;
    tissue.tessellation = laguerre_tessellation(setup);
    const Tessellation& t = tissue.tessellation;
    const TissueScales sc = tissue_scales(setup);
    const double r = setup.vertex_radius;
    ShellModel& model = tissue.model;
    const int ns = setup.edge_segments;
    // corner_vertex[cell][k]: the shell vertex at corner k of the cell.
    std::vector<std::vector<int>> corner_vertex;
    for (const std::vector<int>& corners : t.cells) {
        const int count = static_cast<int>(corners.size());
        const auto C = [&](int k) { return t.corners[corners[(k + count) % count]]; };
        // Inset by r (decision spd-tissue-shrink): the corner moves to the intersection of its two edges
        // shifted inward by r, c + r (n1 + n2)/(1 + n1.n2).
        std::vector<Vec2> inset;
        for (int k = 0; k < count; ++k) {
            const Vec2 n1 = inward_normal(C(k - 1), C(k)), n2 = inward_normal(C(k), C(k + 1));
            inset.push_back(C(k) + r * (n1 + n2) / (1 + n1.dot(n2)));
        }
        Points<2> vertices(2, count * ns);
        for (int k = 0; k < count; ++k) {
            const Vec2 a = inset[k], b = inset[(k + 1) % count];
            if ((b - a).dot(C(k + 1) - C(k)) < 0.25 * (C(k + 1) - C(k)).squaredNorm()) {
                std::ostringstream what;
                what << "r = " << r << " m: the inset by r shortens a cell edge of length "
                     << (C(k + 1) - C(k)).norm() << " m below a quarter of its length; allowed: a smaller r";
                throw InputError(what.str());
            }
            for (int j = 0; j < ns; ++j)
                vertices.col(k * ns + j) = a + (static_cast<double>(j) / ns) * (b - a);
        }
        Shell shell;
        shell.laws = sc.laws;
        shell.depth = setup.material.s;
        shell.radius = r;
        shell.K_Omega = setup.eta * shell_bulk_modulus(sc.laws.k_s, setup.material.s, count * ns);
        const int index = model.add_shell(vertices, shell, setup.vertex_mass);
        tissue.cells.push_back(index);
        std::vector<int> cv;
        for (int k = 0; k < count; ++k)
            cv.push_back(model.shells()[index].first + k * ns);
        corner_vertex.push_back(cv);
    }
    // Interfaces: an edge (A, B) of one cell found as (B, A) in another.
    std::map<std::pair<int, int>, std::pair<int, int>> edge_owner; // (A, B) -> (cell, local k)
    for (std::size_t c = 0; c < t.cells.size(); ++c) {
        const auto& corners = t.cells[c];
        for (std::size_t k = 0; k < corners.size(); ++k)
            edge_owner[{corners[k], corners[(k + 1) % corners.size()]}] = {static_cast<int>(c),
                                                                           static_cast<int>(k)};
    }
    std::vector<CohesiveLink> links;
    const double on_side = 1e-9 * setup.radius;
    for (const auto& [edge, owner] : edge_owner) {
        const auto [A, B] = edge;
        const auto [ci, ki] = owner;
        const auto other = edge_owner.find({B, A});
        if (other != edge_owner.end()) {
            if (A > B) continue; // each interface once
            const auto [cj, kj] = other->second;
            const int count_i = static_cast<int>(t.cells[ci].size()),
                      count_j = static_cast<int>(t.cells[cj].size());
            const int ia = corner_vertex[ci][ki], ib = corner_vertex[ci][(ki + 1) % count_i];
            const int jb = corner_vertex[cj][kj], ja = corner_vertex[cj][(kj + 1) % count_j];
            CohesiveLink at_A{ia, ja, ib, jb}, at_B{ib, jb, ia, ja};
            for (CohesiveLink* link : {&at_A, &at_B}) {
                LinkKinematics k =
                    link_kinematics(*link, model.vertex(link->a), model.vertex(link->b),
                                    model.vertex(link->partner_a), model.vertex(link->partner_b));
                if (k.gap < 0) link->normal_sign = -1, k.gap = -k.gap;
                link->gap0 = k.gap;
                link->slip0 = k.slip;
                links.push_back(*link);
            }
            ++tissue.interfaces;
            continue;
        }
        // A boundary edge: clamped if it lies on the bottom or top line of the box (decision
        // spd-tissue-clamps).
        const int sides = box_sides(t.corners[A], t.width, t.height, on_side) &
                          box_sides(t.corners[B], t.width, t.height, on_side);
        if (!(sides & (4 | 8))) continue;
        const Shell& s = model.shells()[tissue.cells[ci]];
        std::vector<int>& clamp = sides & 4 ? tissue.bottom : tissue.top;
        for (int j = 0; j <= ns; ++j)
            clamp.push_back(s.first + (ki * ns + j) % s.count);
    }
    for (std::vector<int>* clamp : {&tissue.bottom, &tissue.top}) {
        std::sort(clamp->begin(), clamp->end());
        clamp->erase(std::unique(clamp->begin(), clamp->end()), clamp->end());
        for (int i : *clamp) {
            if (!setup.sliding_clamps) model.freeze(i, 0);
            model.freeze(i, 1);
        }
    }
    if (setup.sliding_clamps) model.freeze(tissue.bottom.front(), 0); // no rigid translation along x
    model.set_cohesive_links(std::move(links), sc.link);
    // Broken links: the contact law of eqs. (6)-(7) with mu = 0.3 (section 6), the link's stiffnesses and the
    // normal contact damping of the ring scenes (decision spd-tissue-contact).
    model.set_contact_law(
        {sc.link.k_n, sc.link.k_t, setup.friction, 2 * std::sqrt(setup.vertex_mass * sc.link.k_n)});
    tissue.height0 = clamp_height(tissue);
    return tissue;
}

double top_clamp_force(const Tissue& tissue)
{
    double F = 0; // the tissue pulls the top clamp down; the clamp pulls up with the opposite force
    for (int i : tissue.top)
        F -= tissue.model.force(i).y();
    return F;
}

double bottom_clamp_force(const Tissue& tissue)
{
    double F = 0;
    for (int i : tissue.bottom)
        F += tissue.model.force(i).y();
    return F;
}

double clamp_height(const Tissue& tissue)
{
    return tissue.model.vertex(tissue.top.front()).y() - tissue.model.vertex(tissue.bottom.front()).y();
}

Cohesion cohesion(const Tissue& tissue)
{
    const ShellModel& model = tissue.model;
    const int n = static_cast<int>(tissue.cells.size());
    // Nodes: the cells, then the bottom clamp (n) and the top clamp (n + 1).
    std::vector<int> parent(static_cast<std::size_t>(n + 2));
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<int> cell_of_vertex(static_cast<std::size_t>(model.vertices()));
    for (int c = 0; c < n; ++c) {
        const Shell& s = model.shells()[tissue.cells[c]];
        for (int i = s.first; i < s.first + s.count; ++i)
            cell_of_vertex[i] = c;
    }
    const auto join = [&](int a, int b) { parent[root(parent, a)] = root(parent, b); };
    for (const CohesiveLink& link : model.links())
        if (!link.broken) join(cell_of_vertex[link.a], cell_of_vertex[link.b]);
    for (int i : tissue.bottom)
        join(cell_of_vertex[i], n);
    for (int i : tissue.top)
        join(cell_of_vertex[i], n + 1);
    Cohesion result;
    result.bottom_to_top = root(parent, n) == root(parent, n + 1);
    std::vector<int> roots;
    for (int c = 0; c < n; ++c)
        roots.push_back(root(parent, c));
    std::sort(roots.begin(), roots.end());
    result.groups = static_cast<int>(std::unique(roots.begin(), roots.end()) - roots.begin());
    return result;
}

PullResult pull(Tissue& tissue, const PullSetup& setup, const std::function<void(double)>& progress,
                Checkpoints* checkpoints, const PullObserver& observe)
{
    PullResult result;
    ShellModel& model = tissue.model;
    const Shell& first = model.shells()[tissue.cells.front()];
    const double m = model.min_vertex_mass(), k_s = first.laws.k_s;
    result.dt = setup.dt_factor * critical_time_step(model);
    check_time_step(model, result.dt);
    const double t_c = std::sqrt(m / k_s);
    result.speed = setup.pull_rate * tissue.height0 / t_c;
    for (int i : tissue.top)
        model.set_vertex_velocity(i, Vec2(0, result.speed));
    const double damping = setup.damping * 2 * std::sqrt(m * k_s);
    const double H_end = tissue.height0 * std::exp(setup.strain_max);
    const long total = checked_step_count(std::ceil((H_end - tissue.height0) / (result.speed * result.dt)),
                                          "the pull", "dt_factor", setup.dt_factor);
    const long interval = std::max(1L, total / setup.records);
    const long snapshot_interval = std::max(1L, total / setup.snapshots);
    const auto snapshot = [&] {
        TissueSnapshot snap;
        snap.height = clamp_height(tissue);
        snap.strain = std::log(snap.height / tissue.height0);
        snap.broken = model.broken_links();
        for (int c : tissue.cells) {
            snap.cells.push_back(model.outline(c));
            snap.energy.push_back(model.elastic_energy(c));
        }
        result.snapshots.push_back(std::move(snap));
    };
    const auto record = [&] {
        TissueRecord rec;
        rec.strain = std::log(clamp_height(tissue) / tissue.height0);
        rec.force_top = top_clamp_force(tissue);
        rec.force_bottom = bottom_clamp_force(tissue);
        rec.broken = model.broken_links();
        rec.kinetic_energy = model.kinetic_energy();
        result.records.push_back(rec);
    };
    // The state of a checkpoint: the model, the records so far, the steps taken and the largest force. The
    // time step and speed above come from the tissue as built, before any state is read.
    long taken = 0;
    double force_max = 0;
    const auto whole_state = [&](Archive& archive) {
        archive(model);
        archive(result.records);
        archive(result.snapshots);
        archive(taken);
        archive(force_max);
    };
    if (!checkpoints || !checkpoints->resume(whole_state)) {
        record();
        if (observe) observe(tissue, 0.0);
        snapshot();
    }
    for (long n = taken + 1; n <= total; ++n) {
        model.step(result.dt, damping);
        if (n % snapshot_interval == 0) snapshot();
        taken = n;
        if (n % interval == 0 || n == total) {
            record();
            if (observe) observe(tissue, static_cast<double>(n) * result.dt);
            const TissueRecord& rec = result.records.back();
            force_max = std::max(force_max, rec.force_top);
            progress(static_cast<double>(n) / total);
            // Failed: no intact path of links joins the clamps any more and the load has gone.
            if (rec.broken > 0 && rec.force_top < setup.stop_fraction * force_max &&
                !cohesion(tissue).bottom_to_top)
                break;
        }
        if (checkpoints && checkpoints->due()) checkpoints->save(whole_state);
    }
    if (result.snapshots.back().strain < result.records.back().strain) snapshot();
    result.steps = model.steps();
    return result;
}

void transfer(Archive& archive, TissueSnapshot& snapshot)
{
    archive(snapshot.strain);
    archive(snapshot.height);
    archive(snapshot.cells);
    archive(snapshot.energy);
    archive(snapshot.broken);
}

} // namespace softgrain::spd
