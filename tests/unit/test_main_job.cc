// The built-in default scene is the main job: `greentread` with no scene file
// runs what prm/tyre_road_contact.prm runs, parameter for parameter. The
// .prm is the documented, commented form of the defaults; this test keeps
// the two from drifting apart (a drift would also make a default run miss
// the .prm run's saved Green's functions). And the keys that decide when the
// main job's saved stages are reused.

#include "scratch.h"
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/revision.h>
#include <greentread/config.h>
#include <greentread/modal/patch_model_stage.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/synthesis/mode_stage.h>

#include <filesystem>

#include <boost/test/unit_test.hpp>

#include <tuple>

#include <fstream>
#include <map>
#include <string>

using namespace greentread;

BOOST_AUTO_TEST_SUITE(main_job)

BOOST_AUTO_TEST_CASE(built_in_defaults_are_prm_tyre_road_contact)
{
  dealii::ParameterHandler defaults, main_job;
  scenes::declare_parameters(defaults);
  scenes::declare_parameters(main_job);
  base::parse_scene_file(main_job, GREENTREAD_SOURCE_DIR "/prm/tyre_road_contact.prm");

  std::map<std::string, std::string> from_file;
  for (const auto &[path, value] : base::ParameterRecord::from(main_job, "").entries)
    from_file[path] = value;
  unsigned int compared = 0;
  for (const auto &[path, value] : base::ParameterRecord::from(defaults, "").entries)
    {
      BOOST_TEST_REQUIRE(from_file.count(path) == 1u, path);
      if (path == "Output directory")
        continue; // output/ by default, output/tyre_road_contact for the .prm
      BOOST_TEST(from_file[path] == value, path << ": the .prm has '" << from_file[path]
                                                << "', the default is '" << value << "'");
      ++compared;
    }
  BOOST_TEST_MESSAGE(compared << " parameters: the default equals the main job's .prm");
  BOOST_TEST(compared > 100u);
  BOOST_TEST(defaults.get("Scene") == "tyre-road-contact");
}

BOOST_AUTO_TEST_CASE(stage_keys_change_with_what_the_stages_depend_on_only)
{
  // The keys that decide whether green_functions.h5 and patch_model.h5 are
  // reused: a parameter of the stage changes them; the git revision, the
  // .geo file's path, the output directory and the later stages' parameters
  // do not.
  namespace fs           = std::filesystem;
  const std::string geo  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
  const fs::path    copy = test::scratch_directory("main-job-key") / "greentread_key_test.geo";
  fs::copy_file(geo, copy, fs::copy_options::overwrite_existing);

  const auto keys = [&](const std::vector<std::string> &overrides, const std::string &geo_file) {
    dealii::ParameterHandler prm;
    scenes::declare_parameters(prm);
    for (const auto &o : overrides)
      base::apply_override(prm, o);
    const std::string green = periodic::green_stage_key(prm, geo_file);
    return std::make_tuple(green, modal::patch_model_stage_key(prm, green),
                           synthesis::mode_stage_key(prm, green));
  };
  const auto reference = keys({}, geo);
  BOOST_TEST(std::get<0>(reference).find(base::git_revision()) == std::string::npos);
  BOOST_TEST(std::get<1>(reference).find(base::git_revision()) == std::string::npos);
  BOOST_TEST(std::get<2>(reference).find(base::git_revision()) == std::string::npos);
  BOOST_TEST(std::get<0>(reference).find(".geo") == std::string::npos);

  // Unchanged: another path to the same file, other outputs, later stages.
  BOOST_TEST((keys({}, copy.string()) == reference));
  BOOST_TEST((keys({"Output directory=elsewhere", "Rolling/Speeds (kph)=130",
                    "Road texture/Roads=road-B", "Green's functions/Pairs=0:0"},
                   geo) == reference));

  // Changed: a parameter of the Green's stage changes every key; one of
  // the LSCE fit only its own, the modes' cut-off only the modes'.
  const auto mesh = keys({"Geometry/Mesh size=0.01"}, geo);
  BOOST_TEST(std::get<0>(mesh) != std::get<0>(reference));
  BOOST_TEST(std::get<1>(mesh) != std::get<1>(reference));
  BOOST_TEST(std::get<2>(mesh) != std::get<2>(reference));
  const auto weight = keys({"Patch model/Static weight=10"}, geo);
  BOOST_TEST(std::get<0>(weight) == std::get<0>(reference));
  BOOST_TEST(std::get<1>(weight) != std::get<1>(reference));
  BOOST_TEST(std::get<2>(weight) == std::get<2>(reference));
  const auto cutoff = keys({"Patch model/Mode cutoff=6000"}, geo);
  BOOST_TEST(std::get<0>(cutoff) == std::get<0>(reference));
  BOOST_TEST(std::get<2>(cutoff) != std::get<2>(reference));

  // And the file's contents, not its name.
  {
    std::ofstream append(copy, std::ios::app);
    append << "\n// an edit\n";
  }
  BOOST_TEST(std::get<0>(keys({}, copy.string())) != std::get<0>(reference));
  fs::remove(copy);
}

BOOST_AUTO_TEST_SUITE_END()
