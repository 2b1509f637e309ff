#include "spd/assembly.hpp"

#include "core/rng.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::spd {

Assembly rings_in_box(const AssemblySetup& setup, int columns)
{
    Assembly a;
    Rng rng(setup.seed);
    for (int p = 0; p < setup.particles; ++p) {
        double g = 0;
        if (setup.radius_spread > 0) do
                g = rng.normal(1.0);
            while (std::abs(g) >= 2.0);
        a.radii.push_back(setup.ring.radius * (1 + setup.radius_spread * g));
    }
    const RingScales sc = ring_scales(setup.ring);
    const double r = sc.radius_vertex;
    const double R_max = *std::max_element(a.radii.begin(), a.radii.end());
    const double pitch = 2 * (R_max + r);
    const int rows = (setup.particles + columns - 1) / columns;
    a.width = columns * pitch;
    a.height = rows * pitch;
    for (int p = 0; p < setup.particles; ++p) {
        RingSetup ring = setup.ring;
        ring.radius = a.radii[p];
        const int shell = add_ring(a.model, ring, 0.0);
        a.model.translate(shell, Vec2((p % columns + 0.5) * pitch, (p / columns + 0.5) * pitch));
        a.particles.push_back(shell);
    }
    Shell wall;
    wall.closed = false;
    wall.rigid = true;
    const auto add_wall = [&](double x0, double y0, double x1, double y1) {
        Points<2> ends(2, 2);
        ends << x0, x1, y0, y1;
        return a.model.add_shell(ends, wall, 1.0);
    };
    a.bottom = add_wall(0, 0, a.width, 0);
    a.right = add_wall(a.width, 0, a.width, a.height);
    a.top = add_wall(a.width, a.height, 0, a.height);
    a.left = add_wall(0, a.height, 0, 0);
    const double k_n = sc.laws.k_s;
    a.model.set_contact_law({k_n, 0.0, 0.0, 2 * std::sqrt(setup.ring.vertex_mass * k_n)});
    return a;
}

int particle_vertices(const Assembly& assembly)
{
    int n = 0;
    for (int p : assembly.particles)
        n += assembly.model.shells()[p].count;
    return n;
}

} // namespace softgrain::spd
