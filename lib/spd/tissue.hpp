// SPD section 6 (Trivino et al.): tensile fracture of a cellular tissue (Figs. 30-34).
//
// Set-up (decisions spd-tissue-tessellation, spd-tissue-shrink, spd-tissue-clamps): disks of radii
// R (1 + spread g) (g a standard normal truncated at |g| < 2, decision spd-polydispersity) centred on a
// triangular lattice of pitch 2R fill the box [0, W] x [0, H]; their radical (Laguerre) cells are computed by
// voro++ in a thin slab and cut at mid-plane into polygons; corners closer than 0.2 R are merged (no tiny
// interfaces). Each polygon is inset by the Minkowski radius r (its edges moved inward by r, so that two
// neighbouring cells' sphero-polygons touch along their interface at rest) and its edges split into
// `edge_segments` elements: a closed shell of the SPD model. Each interior interface carries two cohesive
// links, one per end, between the two cells' corner vertices there (lib/spd/cohesive_link.hpp). The vertices
// of the cell edges on the bottom line of the box are clamped, those on the top line move up at constant
// speed; the lateral sides are free.
//
// Measures: sigma = F/(W s) with F the vertical force the clamps exert (top, pulling; bottom, holding),
// eps_h = ln(H/H0) with H the distance between the clamped vertex lines, W_i the elastic energy of cell i
// (ShellModel::elastic_energy) over W0 = (f_n^0)^2/(2 k_n).
#pragma once

#include "spd/calibration.hpp"
#include "spd/cohesive_link.hpp"
#include "spd/shell_model.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace softgrain {
class Checkpoints;
}

namespace softgrain::spd {

struct TissueSetup
{
    int columns = 10;           // cells per row
    int rows = 11;              // rows of cells
    double radius = 1;          // mean disk radius R [m]
    double radius_spread = 0.1; // Delta R/R of the disks (standard deviation)
    std::uint64_t seed = 1;
    int edge_segments = 2;                      // shell elements per cell edge
    double vertex_radius = 0.02;                // Minkowski radius r [m]
    ShellMaterial material{1e6, 0.3, 0.1, 0.1}; // E [Pa], nu, h [m], s [m]
    double eta = 0;                             // core stiffness ratio, eq. (24)
    double plastic_ratio = INFINITY;            // M_b^Y/M*, eq. (32)
    double vertex_mass = 1;                     // [kg]
    double link_stiffness = 0.1;                // k_n / k_s (decision spd-tissue-parameters)
    double shear_stiffness_ratio = 0.1;         // k_t / k_n (typo 3, decision spd-tissue-kt)
    double cohesion = 1;                        // |f_n^0| / F*
    double shear_strength_ratio = 1;            // f_t^0 / |f_n^0|
    double friction = 0.3;                      // mu of broken links (section 6)
    // Clamped vertices: both components fixed, or only the vertical one (the rows slide along the walls,
    // one bottom vertex also fixed in x), decision spd-tissue-clamps.
    bool sliding_clamps = false;
};

// The Laguerre cells: polygons (CCW, corners shared exactly between cells) tiling [0, W] x [0, H].
struct Tessellation
{
    double width = 0, height = 0;
    std::vector<Vec2> centres;
    std::vector<double> radii;
    std::vector<std::vector<int>> cells; // corner indices of each cell, CCW
    std::vector<Vec2> corners;
    double voronoi_area = 0; // sum of the voro++ cell areas before corner merging [m^2]
    int merged_corners = 0;  // corners removed by merging
};
Tessellation laguerre_tessellation(const TissueSetup& setup);
// Sum of the signed areas of the cells (after corner merging) [m^2].
double total_cell_area(const Tessellation& t);

// Scales of the tissue: shell laws (k_s, k_b from eqs. (10)-(11); M_b^Y = plastic_ratio M*, F_s^Y = inf),
// F* = k_b/R and M* = F* l0 (eqs. (30), (32)) with l0 the nominal element length (2R/sqrt(3))/edge_segments,
// the cohesive law and the fracture energy W0 = (f_n^0)^2/(2 k_n).
struct TissueScales
{
    ShellLaws laws;
    double l0 = 0, F_star = 0, M_star = 0, W0 = 0;
    CohesiveLaw link;
};
TissueScales tissue_scales(const TissueSetup& setup);

struct Tissue
{
    Tessellation tessellation;
    ShellModel model;
    std::vector<int> cells;       // shell index of each cell
    std::vector<int> bottom, top; // clamped vertices
    int interfaces = 0;           // interior interfaces (two links each)
    double height0 = 0;           // H0: distance between the clamped vertex lines [m]
};
Tissue build_tissue(const TissueSetup& setup);

// Vertical force the clamps exert on the tissue [N]: top (upward positive) and bottom (downward positive);
// both positive in tension.
double top_clamp_force(const Tissue& tissue);
double bottom_clamp_force(const Tissue& tissue);
double clamp_height(const Tissue& tissue); // H [m]

// Connectivity of the cells through intact links: number of connected groups, and whether any intact path
// joins the bottom clamp to the top clamp.
struct Cohesion
{
    int groups = 0;
    bool bottom_to_top = true;
};
Cohesion cohesion(const Tissue& tissue);

struct TissueRecord
{
    double strain = 0;                      // ln(H/H0)
    double force_top = 0, force_bottom = 0; // [N]
    int broken = 0;
    double kinetic_energy = 0; // [J]
};

struct TissueSnapshot
{
    double strain = 0, height = 0;
    std::vector<std::vector<Vec2>> cells;
    std::vector<double> energy; // W_i [J]
    int broken = 0;
};

struct PullSetup
{
    double pull_rate = 5e-6; // dH/dt / H0 in units of 1/t_c, t_c = sqrt(m/k_s)
    double strain_max = 0.3; // ln(H/H0) at the end, unless the tissue fails first
    // Stop once no intact path joins the clamps and sigma < stop_fraction sigma_max.
    double stop_fraction = 0.02;
    double damping = 0.02;   // global viscous damping over 2 sqrt(m k_s)
    double dt_factor = 0.25; // dt/dt_c
    int records = 2000;
    int snapshots = 40; // stored during loading (the figures pick from them)
};

struct PullResult
{
    std::vector<TissueRecord> records;
    std::vector<TissueSnapshot> snapshots; // the first at eps = 0, the last at the end of the run
    double dt = 0, speed = 0;              // [s], [m/s]
    long steps = 0;
};
// With `checkpoints`, the pull writes its whole state when one is due and, if asked to, starts from the last
// one: the result is the same, bit for bit, as that of an uninterrupted pull of the same tissue.
// observe(tissue, time) is called at each record (time since the pull started [s]), but not again for the
// records a checkpoint restored.
using PullObserver = std::function<void(const Tissue&, double)>;
PullResult pull(Tissue& tissue, const PullSetup& setup, const std::function<void(double)>& progress,
                Checkpoints* checkpoints = nullptr, const PullObserver& observe = {});
// Writes or reads a snapshot for a checkpoint (core/checkpoint.hpp).
void transfer(Archive& archive, TissueSnapshot& snapshot);

} // namespace softgrain::spd
