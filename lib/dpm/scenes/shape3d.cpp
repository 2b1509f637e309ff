// dpm.shape3d: the closed triangulated meshes of section 9.3.1, their Euler counts and the shape
// parameter A^3D = s^(3/2)/(6 sqrt(pi) v) of the undeformed mesh (the text's A_min^3D).
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/shape_energy3d.hpp"
#include "dpm/scenes/scenes.hpp"
#include "dpm/system/mesh3d.hpp"

#include <algorithm>

namespace softgrain::dpm {

namespace {

struct Shape3dOptions
{
    std::string mesh = "geodesic42"; // mesh_from_name
};

OptionBinding<Shape3dOptions> shape3d_binding()
{
    OptionBinding<Shape3dOptions> binding;
    binding.word(&Shape3dOptions::mesh, "mesh", particle_mesh_names(),
                 "closed triangulated surface: Platonic solid or geodesic icosahedron "
                 "(vertices projected to the unit sphere)");
    return binding;
}

// The mesh on the unit sphere and its measures.
struct Shape3dResult
{
    TriangleMesh mesh;
    Eigen::VectorXd x;
    double volume = 0, surface = 0;
    std::vector<double> face_areas, bending_angles;
};

Shape3dResult measure_mesh(const std::string& name)
{
    Shape3dResult result;
    result.mesh = mesh_from_name(name);
    result.x = mesh_coordinates(result.mesh);
    result.volume = mesh_volume(result.mesh, result.x, 0);
    result.surface = mesh_surface_area(result.mesh, result.x, 0);
    result.face_areas = mesh_face_areas(result.mesh, result.x, 0);
    result.bending_angles = mesh_bending_angles(result.mesh, result.x, 0);
    return result;
}

// ParaView: one frame (time value 0) of the bare mesh on the unit sphere (no vertex spheres: radius 0; no
// energy: force 0; volume_ratio 1), with each face's area a_f of faces.dat as cell data face_area and the
// summary's shape parameter, volume and surface as field data.
void write_mesh_frame(const Shape3dResult& result, vtk::Series& series)
{
    vtk::PolyData particle =
        mesh_particles({MeshParticle{&result.mesh, 0, 0.0, result.volume, Eigen::Vector3d::Zero()}}, result.x,
                       Eigen::VectorXd::Zero(result.x.size()));
    particle.cell_scalars("face_area", result.face_areas);
    particle.field("shape_parameter", shape_parameter3d(result.surface, result.volume));
    particle.field("volume", result.volume);
    particle.field("surface_area", result.surface);
    series.write(0.0, {{"particles", std::move(particle)}});
}

void report_shape3d(const Shape3dResult& result, RunContext& context)
{
    const TriangleMesh& mesh = result.mesh;
    const std::vector<double>& areas = result.face_areas;
    const std::vector<double>& angles = result.bending_angles;
    auto& faces =
        context.table("faces.dat", {{"f", "1", "face index"},
                                    {"area", "R^2", "face area a_f (vertices on the unit sphere)"}});
    for (std::size_t f = 0; f < areas.size(); ++f)
        faces.row({double(f), areas[f]});
    auto& summary = context.summary();
    summary["vertices"] = mesh.vertex_count();
    summary["faces"] = mesh.face_count();
    summary["edges"] = mesh.edge_count();
    summary["euler_characteristic"] = mesh.vertex_count() + mesh.face_count() - mesh.edge_count();
    summary["volume"] = result.volume;
    summary["surface_area"] = result.surface;
    summary["shape_parameter_min"] = shape_parameter3d(result.surface, result.volume);
    summary["face_area_ratio"] =
        *std::max_element(areas.begin(), areas.end()) / *std::min_element(areas.begin(), areas.end());
    summary["bending_angle_min"] = *std::min_element(angles.begin(), angles.end());
    summary["bending_angle_max"] = *std::max_element(angles.begin(), angles.end());
    if (auto* series = context.vtk()) write_mesh_frame(result, *series);
}

void run_shape3d(const Shape3dOptions& options, RunContext& context)
{
    report_shape3d(measure_mesh(options.mesh), context);
}

} // namespace

Scene shape3d_scene()
{
    return bound_scene("dpm.shape3d",
                       "DPM sec. 9.3.1: closed triangulated meshes (Platonic solids, geodesic icosahedra), "
                       "Euler counts and the 3D shape parameter A^3D",
                       shape3d_binding(), run_shape3d)
        .with_vtk();
}

} // namespace softgrain::dpm
