#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <vector>

/**
 * @file
 * What turns a scene file and its --set overrides into the parameters the
 * scenes read: the renamed parameters' old spellings, and the input files
 * named relative to the scene file. Implemented in source/scenes/scene_input.cc.
 */

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Declare the old spelling of every renamed parameter, empty by
     * default, so that scene files written for the last release still parse.
     *
     * A rename that keeps its subsection and its unit could be a deal.II
     * ParameterHandler::declare_alias(); two of ours move to another
     * subsection or change unit, which an alias cannot, so all of them go
     * through one table (source/scenes/scene_input.cc) and one warning.
     */
    void
    declare_renamed_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Move every old spelling that is set to its new name (converting
     * its unit where it changed), warn on @p warnings naming both, and reset
     * the old one. Setting both spellings is an InputError.
     */
    void
    apply_renamed_parameters(dealii::ParameterHandler &prm, std::ostream &warnings);

    /**
     * @brief The scene's name with its old spelling ('tire-...') replaced by
     * the new one ('tyre-...'), with a warning on @p warnings.
     */
    std::string
    current_scene_name(const std::string &scene, std::ostream &warnings);

    /**
     * @brief Resolve the input files a scene reads (Geometry file, texture
     * files among the roads, FRF and Green's function files) given as
     * relative paths: first against the folder of @p scene_file, then the
     * working directory, then, for the shipped defaults only, the checkout
     * the program was built from. A file found nowhere is an InputError that
     * names the parameter, the value and every folder searched.
     * Only the entries of @p sections_read (subsections_read()) are
     * resolved: a scene does not look for files it does not read.
     * @param[in] scene_file The scene file, or empty for the built-in scene.
     */
    void
    resolve_input_files(dealii::ParameterHandler       &prm,
                        const std::string              &scene_file,
                        const std::vector<std::string> &sections_read);
  } // namespace scenes
} // namespace greentread
