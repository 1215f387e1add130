// Writes a stand-in for a measured texture file, for the worked example of
// doc/getting-started.md: a road-B-like dense asphalt (the preset's target
// spectrum, seed 7), 0.8 m long (or LENGTH) and 0.1 m wide on a 1 mm grid,
// as ASCII SDF (ISO 25178-71), the format profilometers export, or, for a
// FILE ending in .x3p, as X3P (ISO 25178-72, 16-bit integer heights), the
// format texture scanners write: prm/dense_asphalt.x3p, the patterned-tyre
// scene's second road, is `make_example_road prm/dense_asphalt.x3p 2.4`.
//
//   make_example_road [FILE [LENGTH]]   (default: my_road.sdf 0.8)

#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>
#include <greentread/road/texture_files.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const std::string                        file = argc > 1 ? argv[1] : "my_road.sdf";
  greentread::road::RoadTextureParameters  road;
  road.seed          = 7;
  road.length        = argc > 2 ? std::stod(argv[2]) : 0.8;
  road.spacing       = 1e-3;
  const auto texture = road.make("road-B", 0.1);
  if (file.size() > 4 && file.substr(file.size() - 4) == ".x3p")
    greentread::road::write_x3p(file, texture, 'I');
  else
    greentread::road::write_sdf(file, texture, false);
  std::cout << "wrote " << file << ": " << texture.nx << " x " << texture.ny << " points, "
            << texture.dx * 1e3 << " x " << texture.dy * 1e3 << " mm\n";
  return 0;
}
