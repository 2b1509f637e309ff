#include "dpm/laws/elastic_tetrahedra.hpp"

#include "core/errors.hpp"

namespace softgrain::dpm {

std::array<int, 4> tetrahedron_points(const ElasticTetrahedra& body, int f)
{
    const auto& face = body.mesh.faces[static_cast<std::size_t>(f)];
    return {face[0], face[1], face[2], body.centre()};
}

ElasticTetrahedra elastic_tetrahedra(const TriangleMesh& mesh, const IsotropicElasticity& material)
{
    ElasticTetrahedra body;
    body.mesh = mesh;
    const int n = mesh.vertex_count();
    body.reference.resize(3 * (n + 1));
    body.reference.head(3 * n) = mesh.vertices.reshaped();
    body.reference.tail<3>() = mesh.vertices.rowwise().mean();
    for (int f = 0; f < mesh.face_count(); ++f) {
        const auto local = gather<3, 4>(body.reference, tetrahedron_points(body, f));
        Eigen::Matrix3d X; // eq. (9.16)
        for (int k = 0; k < 3; ++k)
            X.col(k) = local.segment<3>(3 * k) - local.segment<3>(9);
        const double volume = X.determinant() / 6;
        if (!(volume > 0))
            throw NumericalError(
                "reference volume of tetrahedron " + std::to_string(f) + " = " + std::to_string(volume), 0,
                "the surface is not star-shaped about its centroid or not outward-oriented");
        body.tetrahedra.push_back({X.inverse(), volume, material});
    }
    return body;
}

double tetrahedra_energy(const ElasticTetrahedra& body, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                         Eigen::MatrixXd* hessian)
{
    double u = 0;
    for (int f = 0; f < static_cast<int>(body.tetrahedra.size()); ++f) {
        const auto points = tetrahedron_points(body, f);
        u += add_local_term<3, 4>(body.tetrahedra[static_cast<std::size_t>(f)], points,
                                  gather<3, 4>(x, points), gradient, hessian);
    }
    return u;
}

} // namespace softgrain::dpm
