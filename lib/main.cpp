// softgrain: list | describe <scene> | run <scene|file.toml> [--set key=value]... [--out DIR] [--quiet] |
//            advise <scene> --tolerance T [--sweep FILE]
#include "core/cli.hpp"

int main(int argc, char** argv)
{
    return softgrain::run_command_line(argc, argv, softgrain::all_scenes());
}
