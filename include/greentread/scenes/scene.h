#pragma once

#include <greentread/scenes/global_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * A scene is a .prm file: it names what to compute (the top-level `Scene`)
 * and where to put it (`Output directory`). Only the stages a scene needs
 * are built and run.
 */

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief A runnable scene.
     */
    class Scene
    {
    public:
      virtual ~Scene() = default;

      /// Compute and write everything the scene asks for.
      virtual void
      run() = 0;
    };

    /**
     * @brief A scene the program knows: the one place a scene is registered.
     * The 'Scene' parameter's allowed values and documentation, the
     * subsections each scene reads and create_scene() all come from
     * scene_registry().
     */
    struct SceneEntry
    {
      /// Its value of 'Scene'.
      std::string name;
      /// What it computes, for the documentation of 'Scene'.
      std::string description;
      /// The subsections it reads, in the order of its stages, and the
      /// single entries ("Section/Name") it reads from subsections it
      /// shares with others.
      std::vector<std::string> reads;
      /// Whether it may run on more than one MPI rank.
      bool mpi = false;
      std::function<std::unique_ptr<Scene>(dealii::ParameterHandler &, const GlobalParameters &)>
        create;
    };

    /// Every scene, in the order the documentation lists them.
    const std::vector<SceneEntry> &
    scene_registry();

    /**
     * @brief Declare the top-level parameters and every stage's subsection.
     */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Parse and check the parameters of the scene @p prm names, and
     * build it. Nothing is written yet.
     * @throws InputError for any parameter out of range.
     */
    std::unique_ptr<Scene>
    create_scene(dealii::ParameterHandler &prm, const std::string &scene_file = "");

    /**
     * @brief The subsections scene @p scene reads, in the order of its
     * stages (the top-level entries aside), and the single entries
     * ("Section/Name") it reads from subsections it shares with others.
     */
    std::vector<std::string>
    subsections_read(const std::string &scene);

    /// What a scene records with its outputs: "Scene", "Output directory"
    /// and subsections_read().
    std::vector<std::string>
    recorded_sections(const std::string &scene);

    /**
     * @brief Refuse a value set in a subsection that @p scene does not read:
     * it would be silently ignored.
     * @throws InputError naming the parameter, the scene and the subsections
     * it reads.
     */
    void
    check_subsections(const dealii::ParameterHandler &prm, const std::string &scene);
  } // namespace scenes
} // namespace greentread
