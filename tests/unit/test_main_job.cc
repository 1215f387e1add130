// The built-in default scene is the main job: `greentread` with no scene file
// runs what prm/tire_road_contact.prm runs, parameter for parameter. The
// .prm is the documented, commented form of the defaults; this test keeps
// the two from drifting apart (a drift would also make a default run miss
// the .prm run's saved Green's functions).

#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/scenes/scene.h>

#include <boost/test/unit_test.hpp>

#include <map>
#include <string>

using namespace greentread;

BOOST_AUTO_TEST_SUITE(main_job)

BOOST_AUTO_TEST_CASE(built_in_defaults_are_prm_tire_road_contact)
{
  dealii::ParameterHandler defaults, main_job;
  scenes::declare_parameters(defaults);
  scenes::declare_parameters(main_job);
  base::parse_scene_file(main_job, GREENTREAD_SOURCE_DIR "/prm/tire_road_contact.prm");

  std::map<std::string, std::string> from_file;
  for (const auto &[path, value] : base::ParameterRecord::from(main_job, "").entries)
    from_file[path] = value;
  unsigned int compared = 0;
  for (const auto &[path, value] : base::ParameterRecord::from(defaults, "").entries)
    {
      BOOST_TEST_REQUIRE(from_file.count(path) == 1u, path);
      if (path == "Output directory")
        continue; // output/ by default, output/tire_road_contact for the .prm
      BOOST_TEST(from_file[path] == value,
                 path << ": the .prm has '" << from_file[path] << "', the default is '" << value
                      << "'");
      ++compared;
    }
  BOOST_TEST_MESSAGE(compared << " parameters: the default equals the main job's .prm");
  BOOST_TEST(compared > 100u);
  BOOST_TEST(defaults.get("Scene") == "tire-road-contact");
}

BOOST_AUTO_TEST_SUITE_END()
