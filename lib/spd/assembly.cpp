#include "spd/assembly.hpp"

#include "core/checkpoint.hpp"
#include "core/rng.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::spd {

std::vector<double> ring_radii(const AssemblySetup& setup)
{
    std::vector<double> radii;
    Rng rng(setup.seed);
    for (int p = 0; p < setup.particles; ++p) {
        double g = 0;
        if (setup.radius_spread > 0) do
                g = rng.normal(1.0);
            while (std::abs(g) >= 2.0);
        radii.push_back(setup.ring.radius * (1 + setup.radius_spread * g));
    }
    return radii;
}

Assembly rings_at(const AssemblySetup& setup, const std::vector<double>& radii,
                  const std::vector<Vec2>& centres, double width, double height)
{
    Assembly a;
    a.radii = radii;
    a.width = width;
    a.height = height;
    for (std::size_t p = 0; p < radii.size(); ++p) {
        RingSetup ring = setup.ring;
        ring.radius = radii[p];
        const int shell = add_ring(a.model, ring, 0.0);
        a.model.translate(shell, centres[p]);
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
    a.bottom = add_wall(0, 0, width, 0);
    a.right = add_wall(width, 0, width, height);
    a.top = add_wall(width, height, 0, height);
    a.left = add_wall(0, height, 0, 0);
    const double k_n = ring_scales(setup.ring).laws.k_s;
    a.model.set_contact_law({k_n, 0.0, 0.0, 2 * std::sqrt(setup.ring.vertex_mass * k_n)});
    return a;
}

Assembly rings_in_box(const AssemblySetup& setup, int columns)
{
    const std::vector<double> radii = ring_radii(setup);
    const double r = ring_scales(setup.ring).radius_vertex;
    const double R_max = *std::max_element(radii.begin(), radii.end());
    const double pitch = 2 * (R_max + r);
    const int rows = (setup.particles + columns - 1) / columns;
    std::vector<Vec2> centres;
    for (int p = 0; p < setup.particles; ++p)
        centres.emplace_back((p % columns + 0.5) * pitch, (p / columns + 0.5) * pitch);
    return rings_at(setup, radii, centres, columns * pitch, rows * pitch);
}

int particle_vertices(const Assembly& assembly)
{
    int n = 0;
    for (int p : assembly.particles)
        n += assembly.model.shells()[p].count;
    return n;
}

void transfer(Archive& archive, Assembly& assembly)
{
    archive(assembly.model);
    archive(assembly.particles);
    archive(assembly.radii);
    for (int* wall : {&assembly.bottom, &assembly.top, &assembly.left, &assembly.right})
        archive(*wall);
    archive(assembly.width);
    archive(assembly.height);
}

} // namespace softgrain::spd
