// Writes a stand-in for a measured texture file, for the worked example of
// doc/getting-started.md: a road-B-like dense asphalt (the preset's target
// spectrum, seed 7), 0.8 m long and 0.1 m wide on a 1 mm grid, as ASCII SDF
// (ISO 25178-71), the format profilometers export.
//
//   make_example_road [FILE]       (default: my_road.sdf)

#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <deal.II/base/mpi.h>

#include <iostream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const std::string                        file = argc > 1 ? argv[1] : "my_road.sdf";
  greentread::road::RoadTextureParameters  road;
  road.seed          = 7;
  road.length        = 0.8;
  road.spacing       = 1e-3;
  const auto texture = road.make("road-B", 0.1);
  greentread::road::write_sdf(file, texture, false);
  std::cout << "wrote " << file << ": " << texture.nx << " x " << texture.ny << " points, "
            << texture.dx * 1e3 << " x " << texture.dy * 1e3 << " mm\n";
  return 0;
}
