#include "vsm/particle_layouts.hpp"

#include "core/errors.hpp"

namespace softgrain::vsm {

Points<3> jittered_lattice(const Vec3& low, const Vec3& high, const std::array<int, 3>& counts, double jitter,
                           Rng* rng)
{
    if (jitter < 0 || jitter >= 0.5)
        throw InputError("jitter must lie in [0, 0.5); got " + std::to_string(jitter));
    if (jitter > 0 && !rng) throw InputError("a jittered lattice needs a random number generator");
    const Vec3 spacing = (high - low).cwiseQuotient(Vec3(counts[0], counts[1], counts[2]));
    Points<3> X(3, counts[0] * counts[1] * counts[2]);
    int p = 0;
    for (int k = 0; k < counts[2]; ++k)
        for (int j = 0; j < counts[1]; ++j)
            for (int i = 0; i < counts[0]; ++i, ++p) {
                Vec3 position = low + spacing.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
                if (jitter > 0)
                    for (int axis = 0; axis < 3; ++axis)
                        position[axis] += spacing[axis] * rng->uniform(-jitter, jitter);
                X.col(p) = position;
            }
    return X;
}

} // namespace softgrain::vsm
