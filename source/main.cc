// greentread: run a scene.
//
//   greentread [SCENE.prm] [--set "Section/Name=value"]...
//   greentread [SCENE.prm] [--set ...]... --print-parameters=scene
//   greentread --print-parameters[=markdown] | --help | --version
//
// Everything else lives in the greentread_core library, so that the tests and
// benchmarks run the same code.

#include <greentread/base/blas_kernels.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/base/revision.h>
#include <greentread/config.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/scene_input.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/revision.h>

#include <Eigen/Core>

#include <boost/version.hpp>

#include <gmsh.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  const char *usage =
    "Usage:\n"
    "  greentread [SCENE.prm] [--set \"Section/Name=value\"]...\n"
    "  greentread --print-parameters[=markdown]\n"
    "  greentread [SCENE.prm] [--set \"Section/Name=value\"]... --print-parameters=scene\n"
    "  greentread --help | --version\n"
    "\n"
    "Runs the scene SCENE.prm (relative input files are looked for beside it,\n"
    "then in the working directory); without one, the built-in default scene: the main\n"
    "job, the tyre rolling on two road textures at 50, 70 and 90 km/h (the same as\n"
    "prm/tyre_road_contact.prm, writing to output/).\n"
    "\n"
    "Options:\n"
    "  --set \"Path=value\"   override one parameter after the file is read, e.g.\n"
    "                       --set \"Time stepping/Time step=1e-4\"; may be repeated\n"
    "  --print-parameters   every parameter with its default, allowed values, unit\n"
    "                       and meaning; =markdown gives doc/parameters.md;\n"
    "                       =scene prints \"Path = value\" for every parameter as\n"
    "                       SCENE.prm and the --set options give it, and runs nothing\n"
    "  --help               this text\n"
    "  --version            versions of GreenTread and of the libraries it uses\n"
    "\n"
    "Exit status: 0 on success, 2 for bad input (parameter, file, directory),\n"
    "3 for a numerical failure (overflow, divergence, singular system), 1 otherwise.\n";
}



int
main(int argc, char **argv)
{
  greentread::base::use_native_blas_kernels(argv);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  try
    {
      std::string              scene_file;
      std::vector<std::string> overrides;
      std::string              print_parameters;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--help" || arg == "-h")
            {
              std::cout << usage;
              return 0;
            }
          else if (arg == "--version")
            {
              std::cout << "greentread " << GREENTREAD_VERSION << " ("
                        << greentread::base::git_revision() << ", " << GREENTREAD_BUILD_TYPE
                        << ")\n"
                        << "deal.II " << DEAL_II_PACKAGE_VERSION << ", Eigen "
                        << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.'
                        << EIGEN_MINOR_VERSION << ", Boost " << BOOST_VERSION / 100000 << '.'
                        << BOOST_VERSION / 100 % 1000 << ", gmsh " << GMSH_API_VERSION << ", BLAS "
                        << greentread::base::blas_kernels() << '\n';
              return 0;
            }
          else if (arg == "--print-parameters" || arg == "--print-parameters=text")
            print_parameters = "text";
          else if (arg == "--print-parameters=markdown")
            print_parameters = "markdown";
          else if (arg == "--print-parameters=scene")
            print_parameters = "scene";
          else if (arg == "--set")
            {
              if (i + 1 >= argc)
                throw greentread::InputError("--set needs an argument \"Section/Name=value\"");
              overrides.push_back(argv[++i]);
            }
          else if (arg.rfind("--set=", 0) == 0)
            overrides.push_back(arg.substr(6));
          else if (arg.rfind("-", 0) == 0)
            throw greentread::InputError("unknown option '" + arg +
                                         "'; allowed: --set, --print-parameters, --help, "
                                         "--version");
          else if (scene_file.empty())
            scene_file = arg;
          else
            throw greentread::InputError("more than one scene file given ('" + scene_file +
                                         "' and '" + arg + "'); run them one at a time");
        }

      dealii::ParameterHandler prm;
      greentread::scenes::declare_parameters(prm);
      if (print_parameters == "text")
        {
          greentread::base::print_parameter_reference(prm, std::cout);
          return 0;
        }
      if (print_parameters == "markdown")
        {
          greentread::base::print_parameter_markdown(prm, std::cout);
          return 0;
        }
      if (!scene_file.empty())
        greentread::base::parse_scene_file(prm, scene_file);
      for (const auto &assignment : overrides)
        greentread::base::apply_override(prm, assignment);
      greentread::scenes::apply_renamed_parameters(prm, std::cerr);
      if (print_parameters == "scene")
        {
          for (const auto &e : greentread::base::list_parameters(prm))
            std::cout << e.path << " = " << e.value << '\n';
          return 0;
        }

      auto scene = greentread::scenes::create_scene(prm, scene_file);
      scene->run();
    }
  // Bad input and numerical failures are found by every rank alike (the
  // parallel stage shares its failures): rank 0 reports them.
  catch (const greentread::InputError &e)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "greentread: error: " << e.what() << std::endl;
      return 2;
    }
  catch (const greentread::NumericalError &e)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "greentread: numerical failure: " << e.what() << std::endl;
      return 3;
    }
  catch (const std::exception &e)
    {
      // Possibly on one rank only: stop the others rather than leave them
      // waiting.
      std::cerr << "greentread: internal error: " << e.what() << std::endl;
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
  return 0;
}
