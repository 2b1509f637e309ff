// softgrain: list | describe <scene> | run <scene|file.toml> [--set key=value]... [--out DIR] [--quiet] |
//            advise <scene> --tolerance T [--sweep FILE]
#include "core/cli.hpp"
#include "core/ensemble.hpp"

int main(int argc, char** argv)
{
    const softgrain::ParallelSession mpi(argc, argv); // MPI under mpirun or srun (core/ensemble.hpp)
    return softgrain::run_command_line(argc, argv, softgrain::all_scenes());
}
