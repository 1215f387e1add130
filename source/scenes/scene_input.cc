#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/config.h>
#include <greentread/road/patch_road.h>
#include <greentread/scenes/scene_input.h>

#include <array>
#include <filesystem>
#include <sstream>
#include <vector>

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      /// A renamed parameter: its old path, its new path, and the factor
      /// from the old unit to the new one (1 when only the name changed).
      struct Rename
      {
        const char *old_path;
        const char *new_path;
        double      factor;
      };

      /// Every rename of this release. The old spellings go in the next one.
      constexpr std::array<Rename, 4> renames = {{
        {"Rolling/Speeds", "Rolling/Speeds (kph)", 1.},
        {"Oscillator/Speed", "Oscillator/Speed (kph)", 3.6},
        {"Road texture/Sinusoid amplitude", "Road/Sinusoid/Amplitude", 1.},
        {"Road texture/Sinusoid wavelength", "Road/Sinusoid/Wavelength", 1.},
      }};

      std::vector<std::string>
      split_path(const std::string &path)
      {
        std::vector<std::string> parts;
        std::stringstream        in(path);
        std::string              part;
        while (std::getline(in, part, '/'))
          parts.push_back(part);
        return parts;
      }

      /// Call @p f with @p prm inside the subsections of @p path, and the
      /// entry's own name.
      template <typename F>
      auto
      at_path(dealii::ParameterHandler &prm, const std::string &path, F &&f)
      {
        const auto parts = split_path(path);
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        struct Leave
        {
          dealii::ParameterHandler &prm;
          std::size_t               n;
          ~Leave()
          {
            for (std::size_t i = 0; i < n; ++i)
              prm.leave_subsection();
          }
        } leave{prm, parts.size() - 1};
        return f(parts.back());
      }

      std::string
      get(dealii::ParameterHandler &prm, const std::string &path)
      {
        return at_path(prm, path, [&](const std::string &name) {
          return prm.get(name);
        });
      }

      void
      set(dealii::ParameterHandler &prm, const std::string &path, const std::string &value)
      {
        at_path(prm, path, [&](const std::string &name) {
          prm.set(name, value);
        });
      }

      /// Each number of a comma-separated list times @p factor.
      std::string
      convert(const std::string &old_path, const std::string &value, const double factor)
      {
        if (factor == 1.)
          return value;
        std::string out;
        for (const auto &item : base::split_list(value))
          {
            std::size_t end = 0;
            double      x   = 0.;
            try
              {
                x = std::stod(item, &end);
              }
            catch (const std::exception &)
              {
                end = 0;
              }
            if (end == 0 || base::trim(item.substr(end)) != "")
              throw InputError("parameter '" + old_path + "' = " + value +
                               " is not allowed; allowed: a number");
            out += (out.empty() ? "" : ", ") + format_printf("%.12g", factor * x);
          }
        return out;
      }
    } // namespace



    void
    declare_renamed_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &r : renames)
        at_path(prm, r.old_path, [&](const std::string &name) {
          prm.declare_entry(
            name, "", dealii::Patterns::Anything(),
            std::string("Deprecated: the old spelling of '") + r.new_path + "'" +
              (r.factor != 1. ? " in the old unit (times " + format_number(r.factor) + ")" : "") +
              "; still read, with a warning, in this release.");
        });
    }



    void
    apply_renamed_parameters(dealii::ParameterHandler &prm, std::ostream &warnings)
    {
      for (const auto &r : renames)
        {
          const std::string value = get(prm, r.old_path);
          if (value.empty())
            continue;
          std::string allowed;
          for (const auto &e : base::list_parameters(prm))
            if (e.path == r.new_path)
              {
                if (e.value != e.default_value)
                  throw InputError("parameters '" + std::string(r.old_path) + "' = " + value +
                                   " and '" + r.new_path + "' = " + e.value +
                                   " are both set, and the first is the old spelling of the "
                                   "second; allowed: one of them ('" +
                                   r.new_path + "')");
                allowed = e.allowed;
              }
          const std::string converted = convert(r.old_path, value, r.factor);
          try
            {
              set(prm, r.new_path, converted);
            }
          catch (const dealii::ExceptionBase &)
            {
              throw InputError("parameter '" + std::string(r.old_path) + "' = " + value +
                               " (the old spelling of '" + r.new_path + "' = " + converted +
                               ") is not allowed; allowed: " + allowed);
            }
          set(prm, r.old_path, "");
          warnings << "greentread: warning: parameter '" << r.old_path
                   << "' is deprecated: it was read as '" << r.new_path << "' = " << converted
                   << "; use that name (the old one goes in the next release)\n";
        }
    }



    std::string
    current_scene_name(const std::string &scene, std::ostream &warnings)
    {
      if (scene.rfind("tire-", 0) != 0)
        return scene;
      const std::string name = "tyre-" + scene.substr(5);
      warnings << "greentread: warning: scene '" << scene << "' is deprecated: it was read as '"
               << name << "'; use that name (the old one goes in the next release)\n";
      return name;
    }



    void
    resolve_input_files(dealii::ParameterHandler       &prm,
                        const std::string              &scene_file,
                        const std::vector<std::string> &sections_read)
    {
      namespace fs = std::filesystem;
      std::vector<fs::path> folders;
      if (!scene_file.empty())
        folders.push_back(fs::absolute(scene_file).parent_path());
      folders.push_back(fs::current_path());

      const auto resolve = [&](const std::string &path, const std::string &value,
                               const bool shipped_default) -> std::string {
        if (value.empty() || fs::path(value).is_absolute())
          return value;
        std::vector<fs::path> where = folders;
        if (shipped_default)
          where.push_back(fs::path(GREENTREAD_SOURCE_DIR));
        for (const auto &folder : where)
          if (fs::exists(folder / value))
            // Found in the working directory: keep the name as written.
            return folder == fs::current_path() ? value :
                                                  (folder / value).lexically_normal().string();
        std::string searched;
        for (const auto &folder : where)
          searched += (searched.empty() ? "" : ", ") + folder.string();
        throw InputError("parameter '" + path + "' = " + value +
                         ": no such file; a relative path is looked for in the scene file's "
                         "folder, then in the working directory (searched: " +
                         searched + "); allowed: an existing file");
      };

      const auto reads = [&](const std::string &path) {
        for (const auto &s : sections_read)
          if (path.rfind(s + "/", 0) == 0 || path == s)
            return true;
        return false;
      };
      // The shipped tyre, which the built-in scene names relative to the
      // checkout: found from any working directory.
      const std::string shipped_geometry = "geometry/tyre_165_65_r13.geo";
      for (const std::string path :
           {"Geometry/Geometry file", "Identification/FRF file",
            "Identification/Green's function file", "Tread pattern/Footprint image"})
        if (reads(path))
          {
            const std::string value = get(prm, path);
            set(prm, path, resolve(path, value, value == shipped_geometry));
          }

      if (reads("Road texture/Roads"))
        {
          std::string roads;
          for (const auto &road : base::split_list(get(prm, "Road texture/Roads")))
            roads += (roads.empty() ? "" : ", ") + (road::RoadTextureParameters::is_built_in(road) ?
                                                      road :
                                                      resolve("Road texture/Roads", road, false));
          set(prm, "Road texture/Roads", roads);
        }
    }
  } // namespace scenes
} // namespace greentread
