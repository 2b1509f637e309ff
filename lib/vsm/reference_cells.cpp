// Reference Voronoi cells with mirrored ghosts (Frenning 2022, section 2.1) from voro++.
#include "vsm/reference_cells.hpp"

#include "core/errors.hpp"

#include <Eigen/Geometry>
#include <voro++.hh>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

namespace softgrain::vsm {

namespace {

BoundaryFace make_face(int axis, double position, double outward, Vec3 low, Vec3 high, int label)
{
    low[axis] = position;
    high[axis] = position;
    return BoundaryFace{axis, position, outward, low, high, label};
}

// Geometry of one Voronoi face from voro++'s vertex loop (vertices relative to the particle): area and
// centroid relative to the particle, by a triangle fan.
struct FaceGeometry
{
    double area = 0;
    Vec3 centroid_relative = Vec3::Zero();
    double radius = 0; // largest distance of a vertex from the centroid
};

FaceGeometry face_geometry(const std::vector<double>& vertices, const std::vector<int>& loop,
                           std::size_t first, int count)
{
    const auto vertex = [&](int k) {
        const int v = loop[first + static_cast<std::size_t>(k)];
        return Vec3(vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]);
    };
    const Vec3 p0 = vertex(0);
    Vec3 area_vector = Vec3::Zero(), weighted = Vec3::Zero();
    std::vector<Vec3> triangle_areas;
    for (int k = 1; k + 1 < count; ++k) {
        const Vec3 p1 = vertex(k), p2 = vertex(k + 1);
        const Vec3 twice = (p1 - p0).cross(p2 - p0);
        area_vector += 0.5 * twice;
        triangle_areas.push_back(0.5 * twice);
    }
    const double area = area_vector.norm();
    if (area == 0) return FaceGeometry{0, p0};
    const Vec3 n = area_vector / area;
    for (int k = 1; k + 1 < count; ++k)
        weighted +=
            triangle_areas[static_cast<std::size_t>(k - 1)].dot(n) * (p0 + vertex(k) + vertex(k + 1)) / 3.0;
    const Vec3 centroid = weighted / area;
    double radius = 0;
    for (int k = 0; k < count; ++k)
        radius = std::max(radius, (vertex(k) - centroid).norm());
    return FaceGeometry{area, centroid, radius};
}

struct VoronoiFace
{
    int neighbour;
    FaceGeometry geometry;
};
struct VoronoiCell
{
    double volume = 0;
    std::vector<VoronoiFace> faces;
};

// voro++'s neighbour id of a face on the spherical wall (its container walls are -1 ... -6).
constexpr int sphere_wall_id = -7;

// Voronoi cells of all points (one per column) inside the box [low, high] (non-periodic walls), each cut by
// its tangent plane to the sphere |X| = sphere_radius when that is > 0 (voro++'s wall_sphere).
std::vector<VoronoiCell> compute_cells(const Points<3>& points, const Vec3& low, const Vec3& high,
                                       double sphere_radius)
{
    const int n = static_cast<int>(points.cols());
    const Vec3 size = high - low;
    const double block = std::cbrt(size.prod() / std::max(1, n) * 5.0); // about five points per block
    const auto blocks = [&](int axis) {
        return std::max(1, static_cast<int>(std::ceil(size[axis] / block)));
    };
    voro::container container(low.x(), high.x(), low.y(), high.y(), low.z(), high.z(), blocks(0), blocks(1),
                              blocks(2), false, false, false, 8);
    voro::wall_sphere sphere(0, 0, 0, sphere_radius, sphere_wall_id);
    if (sphere_radius > 0) container.add_wall(sphere);
    for (int i = 0; i < n; ++i)
        container.put(i, points(0, i), points(1, i), points(2, i));
    std::vector<VoronoiCell> cells(static_cast<std::size_t>(n));
    std::vector<bool> computed(static_cast<std::size_t>(n), false);
    voro::c_loop_all loop(container);
    voro::voronoicell_neighbor cell;
    std::vector<int> neighbours, face_loop;
    std::vector<double> vertices;
    if (loop.start()) do {
            if (!container.compute_cell(cell, loop)) continue;
            const int id = loop.pid();
            VoronoiCell& out = cells[static_cast<std::size_t>(id)];
            out.volume = cell.volume();
            cell.neighbors(neighbours);
            cell.face_vertices(face_loop);
            cell.vertices(vertices);
            std::size_t cursor = 0;
            for (int neighbour : neighbours) {
                const int count = face_loop[cursor];
                out.faces.push_back({neighbour, face_geometry(vertices, face_loop, cursor + 1, count)});
                cursor += static_cast<std::size_t>(count) + 1;
            }
            computed[static_cast<std::size_t>(id)] = true;
        } while (loop.inc());
    for (int i = 0; i < n; ++i)
        if (!computed[static_cast<std::size_t>(i)])
            throw InputError("voro++ could not compute the Voronoi cell of point " + std::to_string(i) +
                             " (coincident points?)");
    return cells;
}

bool projects_onto(const BoundaryFace& face, const Vec3& X, double tolerance)
{
    for (int k = 0; k < 3; ++k) {
        if (k == face.axis) continue;
        if (X[k] < face.low[k] - tolerance || X[k] > face.high[k] + tolerance) return false;
    }
    return true;
}

bool inside(const Domain& domain, const Vec3& X)
{
    if (domain.sphere_radius > 0 && !(X.norm() < domain.sphere_radius)) return false;
    for (const auto& [low, high] : domain.boxes)
        if ((X.array() > low.array()).all() && (X.array() < high.array()).all()) return true;
    return false;
}

} // namespace

Domain box_domain(const Vec3& low, const Vec3& high)
{
    Domain d;
    for (int axis = 0; axis < 3; ++axis) {
        d.faces.push_back(make_face(axis, low[axis], -1, low, high, 2 * axis));
        d.faces.push_back(make_face(axis, high[axis], +1, low, high, 2 * axis + 1));
    }
    d.boxes = {{low, high}};
    d.low = low;
    d.high = high;
    d.volume = (high - low).prod();
    return d;
}

Domain l_block_domain(double a, double b, double t)
{
    if (!(t < a && t < b && t > 0)) throw InputError("L-shaped block: need 0 < t < a and t < b");
    Domain d;
    const auto add = [&](int axis, double position, double outward, Vec3 low, Vec3 high, int label) {
        d.faces.push_back(make_face(axis, position, outward, low, high, label));
    };
    // Faces of the horizontal arm [0,a]x[0,t]x[0,t] and the vertical arm [0,t]x[0,b]x[0,t].
    add(0, a, +1, Vec3(a, 0, 0), Vec3(a, t, t), 0);   // loaded end X1 = a
    add(1, b, +1, Vec3(0, b, 0), Vec3(t, b, t), 1);   // loaded end X2 = b
    add(0, 0.0, -1, Vec3(0, 0, 0), Vec3(0, b, t), 2); // X1 = 0
    add(1, 0.0, -1, Vec3(0, 0, 0), Vec3(a, 0, t), 2); // X2 = 0
    add(1, t, +1, Vec3(t, t, 0), Vec3(a, t, t), 2);   // top of the horizontal arm
    add(0, t, +1, Vec3(t, t, 0), Vec3(t, b, t), 2);   // side of the vertical arm
    add(2, 0.0, -1, Vec3(0, 0, 0), Vec3(a, t, 0), 2); // X3 = 0, horizontal arm
    add(2, 0.0, -1, Vec3(0, t, 0), Vec3(t, b, 0), 2); // X3 = 0, vertical arm above it
    add(2, t, +1, Vec3(0, 0, t), Vec3(a, t, t), 2);   // X3 = t, horizontal arm
    add(2, t, +1, Vec3(0, t, t), Vec3(t, b, t), 2);   // X3 = t, vertical arm above it
    d.boxes = {{Vec3::Zero(), Vec3(a, t, t)}, {Vec3::Zero(), Vec3(t, b, t)}};
    d.low = Vec3::Zero();
    d.high = Vec3(a, b, t);
    d.volume = a * t * t + t * (b - t) * t;
    return d;
}

Domain ball_octant_domain(double R)
{
    if (!(R > 0)) throw InputError("ball octant: the radius must be positive");
    const Vec3 high = Vec3::Constant(R);
    Domain d;
    for (int axis = 0; axis < 3; ++axis)
        d.faces.push_back(make_face(axis, 0.0, -1, Vec3::Zero(), high, axis));
    d.boxes = {{Vec3::Zero(), high}};
    d.high = high;
    d.volume = std::acos(-1.0) * R * R * R / 6;
    d.sphere_radius = R;
    d.sphere_label = 3;
    return d;
}

namespace {

// The ghost of particle a across the sphere: the face its tangent plane cut from its cell (section 2.1 with
// W_ab the closest point on the sphere).
Neighbour sphere_ghost(const Vec3& X_a, const FaceGeometry& face, const Domain& domain)
{
    const Vec3 W = domain.sphere_radius * X_a.normalized();
    const Vec3 ghost = 2 * W - X_a;
    Neighbour nb;
    nb.label = domain.sphere_label;
    nb.branch = ghost - X_a;
    nb.length = nb.branch.norm();
    nb.area = face.area;
    nb.normal = nb.branch / nb.length;
    nb.centroid = face.centroid_relative + X_a;
    nb.B_ab = gradient_vector(nb.area, nb.length, nb.centroid, X_a);
    nb.B_ba = gradient_vector(nb.area, nb.length, nb.centroid, ghost);
    nb.boundary_point = W;
    return nb;
}

// Upper bound of the volume a spherical facet of area A adds to the ball: the sphere lies below the tangent
// plane at W by R - sqrt(R^2 - s^2) at the distance s from W, and no point of the facet is farther from W
// than its radius plus the distance of its centroid from W.
double sliver_bound(const Neighbour& nb, const FaceGeometry& face, double R)
{
    const double s = std::min(R, face.radius + (nb.centroid - nb.boundary_point).norm());
    return nb.area * (R - std::sqrt(R * R - s * s));
}

} // namespace

ReferenceCells build_reference_cells(const Points<3>& X, const Domain& domain, double mirror_distance)
{
    const int n = static_cast<int>(X.cols());
    const double extent = (domain.high - domain.low).maxCoeff();
    const double tolerance = 1e-12 * extent;
    for (int a = 0; a < n; ++a)
        if (!inside(domain, X.col(a))) {
            std::ostringstream m;
            m << "particle " << a << " at (" << X(0, a) << ", " << X(1, a) << ", " << X(2, a)
              << ") is not strictly inside the domain";
            throw InputError(m.str());
        }

    // Ghosts: mirror images across every face a particle projects onto within mirror_distance (section 2.1).
    // Mirrors of different particles that coincide (the re-entrant edge of an L-shaped block on a regular
    // lattice) are one point of the diagram; each real particle keeps its own pair (a, ghost).
    std::vector<Vec3> ghosts;
    std::map<std::tuple<long long, long long, long long>, int> ghost_index;
    std::map<std::pair<int, int>, int> owner_face; // (real a, ghost g) -> face index
    const double key_scale = 1.0 / (1e-9 * extent);
    for (int a = 0; a < n; ++a)
        for (std::size_t f = 0; f < domain.faces.size(); ++f) {
            const BoundaryFace& face = domain.faces[f];
            const double depth = face.outward * (face.position - X(face.axis, a));
            if (depth > mirror_distance || !projects_onto(face, X.col(a), tolerance)) continue;
            Vec3 ghost = X.col(a);
            ghost[face.axis] = 2 * face.position - X(face.axis, a);
            if (inside(domain, ghost))
                throw InputError("the mirror of particle " + std::to_string(a) +
                                 " lies inside the domain: reduce mirror_distance");
            const auto key =
                std::make_tuple(std::llround(ghost.x() * key_scale), std::llround(ghost.y() * key_scale),
                                std::llround(ghost.z() * key_scale));
            auto [it, added] = ghost_index.try_emplace(key, static_cast<int>(ghosts.size()));
            if (added) ghosts.push_back(ghost);
            owner_face[{a, it->second}] = static_cast<int>(f);
        }

    Points<3> all(3, n + static_cast<Eigen::Index>(ghosts.size()));
    all.leftCols(n) = X;
    for (std::size_t g = 0; g < ghosts.size(); ++g)
        all.col(n + static_cast<Eigen::Index>(g)) = ghosts[g];
    const Vec3 margin = Vec3::Constant(mirror_distance + 1e-3 * extent);
    const std::vector<VoronoiCell> cells =
        compute_cells(all, domain.low - margin, domain.high + margin, domain.sphere_radius);

    ReferenceCells ref;
    ref.X = X;
    ref.ghost_count = static_cast<int>(ghosts.size());
    ref.volume.resize(static_cast<std::size_t>(n));
    ref.neighbours.resize(static_cast<std::size_t>(n));
    ref.B_self.assign(static_cast<std::size_t>(n), Vec3::Zero());
    double total_volume = 0;
    double mean_area = std::pow(domain.volume / n, 2.0 / 3.0);
    const double negligible_area = 1e-12 * mean_area;

    // Real-real faces are taken once, from the cell of the lower index, so that B_ab and B_ba use the same
    // face geometry (this makes eq. (11) exact); a face seen only from one side (a degenerate, zero-area face
    // of a regular lattice) is still entered on both sides. Under a sphere each cell is cut by its own
    // tangent plane, so the two cells of a pair near the surface may clip their common face differently:
    // there each side keeps the face as its own cell bounds it (a side that does not see it gets zero
    // area), which closes every cell, sum_b X_ab (x) B_ab = V_a I, and keeps F_a exact for affine fields.
    std::map<std::pair<int, int>, FaceGeometry> shared, seen_from; // seen_from[(a, b)]: a's own view
    const bool own_views = domain.sphere_radius > 0;
    for (int a = 0; a < n; ++a) {
        const VoronoiCell& cell = cells[static_cast<std::size_t>(a)];
        ref.volume[static_cast<std::size_t>(a)] = cell.volume;
        total_volume += cell.volume;
        for (const VoronoiFace& face : cell.faces) {
            const int b = face.neighbour;
            if (b == sphere_wall_id) continue;
            if (b < 0)
                throw InputError("the cell of particle " + std::to_string(a) +
                                 " reaches the container wall: increase mirror_distance");
            if (b >= n) continue;
            FaceGeometry g = face.geometry;
            g.centroid_relative += X.col(a); // absolute centroid
            const auto key = std::minmax(a, b);
            if (a == key.first || !shared.count(key)) shared[key] = g;
            seen_from[{a, b}] = g;
        }
    }
    const auto view = [&](int p, int q, const FaceGeometry& common) {
        if (!own_views) return common;
        const auto own = seen_from.find({p, q});
        return own != seen_from.end() ? own->second : FaceGeometry{0, common.centroid_relative, 0};
    };
    for (const auto& [key, g] : shared) {
        const auto [a, b] = key;
        for (int side = 0; side < 2; ++side) {
            const int p = side == 0 ? a : b, q = side == 0 ? b : a;
            Neighbour nb;
            nb.particle = q;
            nb.branch = X.col(q) - X.col(p);
            nb.length = nb.branch.norm();
            const FaceGeometry mine = view(p, q, g), theirs = view(q, p, g);
            nb.area = mine.area;
            nb.normal = nb.branch / nb.length;
            nb.centroid = mine.centroid_relative;
            nb.B_ab = gradient_vector(mine.area, nb.length, nb.centroid, X.col(p));
            nb.B_ba = gradient_vector(theirs.area, nb.length, theirs.centroid_relative, X.col(q));
            ref.neighbours[static_cast<std::size_t>(p)].push_back(nb);
        }
    }
    double sliver_volume = 0; // bound of the cells' volume outside a spherical boundary
    for (int a = 0; a < n; ++a) {
        const VoronoiCell& cell = cells[static_cast<std::size_t>(a)];
        for (const VoronoiFace& face : cell.faces) {
            if (face.neighbour == sphere_wall_id) {
                if (face.geometry.area < negligible_area) continue;
                Neighbour nb = sphere_ghost(X.col(a), face.geometry, domain);
                sliver_volume += sliver_bound(nb, face.geometry, domain.sphere_radius);
                ref.neighbours[static_cast<std::size_t>(a)].push_back(nb);
                ++ref.ghost_count;
                continue;
            }
            const int g = face.neighbour - n;
            if (g < 0) continue;
            const auto owner = owner_face.find({a, g});
            if (owner == owner_face.end()) {
                if (face.geometry.area < negligible_area)
                    continue; // degenerate contact with another's mirror
                throw InputError("particle " + std::to_string(a) +
                                 " shares a Voronoi face with the mirror of " +
                                 "another particle: the domain is not resolved by the ghosts");
            }
            Neighbour nb;
            nb.face = owner->second;
            nb.label = domain.faces[static_cast<std::size_t>(nb.face)].label;
            nb.branch = ghosts[static_cast<std::size_t>(g)] - X.col(a);
            nb.length = nb.branch.norm();
            nb.area = face.geometry.area;
            nb.normal = nb.branch / nb.length;
            nb.centroid = face.geometry.centroid_relative + X.col(a);
            nb.B_ab = gradient_vector(nb.area, nb.length, nb.centroid, X.col(a));
            nb.B_ba = gradient_vector(nb.area, nb.length, nb.centroid, ghosts[static_cast<std::size_t>(g)]);
            nb.boundary_point = 0.5 * (X.col(a) + ghosts[static_cast<std::size_t>(g)]);
            ref.neighbours[static_cast<std::size_t>(a)].push_back(nb);
        }
    }
    for (int a = 0; a < n; ++a) {
        auto& list = ref.neighbours[static_cast<std::size_t>(a)];
        // Reverse indices: where a appears in the list of its real neighbour b.
        for (auto& nb : list) {
            if (nb.ghost()) continue;
            const auto& other = ref.neighbours[static_cast<std::size_t>(nb.particle)];
            for (std::size_t k = 0; k < other.size(); ++k)
                if (other[k].particle == a) nb.reverse = static_cast<int>(k);
        }
        Vec3 sum = Vec3::Zero();
        for (const auto& nb : list)
            sum += nb.B_ab;
        ref.B_self[static_cast<std::size_t>(a)] = -sum; // eq. (9)
    }
    // Flat faces: the cells tile D exactly. A sphere: they cover it (every point of the ball lies below every
    // tangent plane), and exceed it by at most the slivers under the spherical facets.
    const double slack = 1e-9 * domain.volume;
    if (total_volume < domain.volume - slack || total_volume > domain.volume + sliver_volume + slack) {
        std::ostringstream m;
        m.precision(12);
        m << "the reference Voronoi cells do not tile the domain: sum V_a = " << total_volume
          << " but |D| = " << domain.volume;
        if (domain.sphere_radius > 0) m << " (+ at most " << sliver_volume << " of spherical slivers)";
        m << " (mirror_distance " << mirror_distance << " too small?)";
        throw InputError(m.str());
    }
    return ref;
}

} // namespace softgrain::vsm
