#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

/**
 * @file
 * The top-level parameters every scene has: which scene, where its outputs
 * go, whether saved results are reused and timings printed
 * (scenes::GlobalParameters); the scenes themselves are in
 * greentread/scenes/scene.h. Implemented in
 * source/scenes/global_parameters.cc.
 */

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief The top-level parameters every scene has.
     */
    struct GlobalParameters
    {
      std::string scene            = "sdof";
      std::string output_directory = "output";
      bool        print_timings    = true;
      bool        reuse            = true;

      /// The scenes' names, from scene_registry(), as a list for messages.
      static std::string
      scene_names();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace scenes
} // namespace greentread
