// Uses the installed library: the period of a spring integrated by velocity Verlet at dt = T/100.
#include <core/harmonic.hpp>

#include <cmath>
#include <cstdio>

int main()
{
    const softgrain::HarmonicOscillator oscillator{1.0, 4.0};
    const double dt = oscillator.period() / 100.0;
    const auto run = softgrain::simulate_harmonic(oscillator, dt, 10.0);
    const double relative = std::abs(run.period / softgrain::verlet_period(oscillator, dt) - 1.0);
    std::printf("period %.9f, exact discrete %.9f\n", run.period, softgrain::verlet_period(oscillator, dt));
    return relative < 1e-6 ? 0 : 1;
}
