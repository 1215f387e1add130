#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/revision.h>
#include <greentread/config.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <sstream>

namespace greentread
{
  namespace base
  {
    ParameterRecord
    ParameterRecord::from(const dealii::ParameterHandler &prm,
                          const std::string              &scene,
                          const std::vector<std::string> &prefixes)
    {
      ParameterRecord record;
      record.header = std::string("greentread ") + GREENTREAD_VERSION + " (" + git_revision() +
                      "), scene " + scene;
      for (const auto &e : list_parameters(prm))
        {
          bool used = prefixes.empty();
          for (const auto &p : prefixes)
            used = used || e.path.rfind(p, 0) == 0;
          if (used)
            record.entries.emplace_back(e.path, e.value);
        }
      return record;
    }



    void
    ParameterRecord::write_comments(std::ostream &out, const std::string &comment) const
    {
      out << comment << header << '\n';
      for (const auto &[path, value] : entries)
        out << comment << path << " = " << value << '\n';
    }



    std::string
    ParameterRecord::text() const
    {
      std::ostringstream s;
      write_comments(s, "");
      return s.str();
    }



    AtomicFile::AtomicFile(const std::filesystem::path &final_path_, const std::ios::openmode mode)
        : final_path(final_path_)
        , tmp_path(final_path_.string() + ".tmp." + std::to_string(::getpid()))
    {
      out.open(tmp_path, mode | std::ios::out | std::ios::trunc);
      if (!out)
        throw InputError("cannot write '" + tmp_path.string() + "': " + std::strerror(errno));
      out.precision(12);
    }



    AtomicFile::~AtomicFile()
    {
      if (!committed)
        {
          out.close();
          std::error_code ignored;
          std::filesystem::remove(tmp_path, ignored);
        }
    }



    void
    AtomicFile::commit()
    {
      bool good = true;
      if (out.is_open())
        {
          out.flush();
          good = out.good();
          out.close();
        }
      if (!good)
        throw InputError("writing '" + final_path.string() + "' failed (disk full or removed?)");
      std::error_code error;
      std::filesystem::rename(tmp_path, final_path, error);
      if (error)
        throw InputError("cannot rename '" + tmp_path.string() + "' to '" + final_path.string() +
                         "': " + error.message());
      committed = true;
    }



    std::filesystem::path
    prepare_output_directory(const std::string &directory)
    {
      if (directory.empty())
        throw InputError("parameter 'Output directory' is empty: give a directory name");
      const std::filesystem::path path(directory);
      std::error_code             error;
      if (std::filesystem::exists(path, error) && !std::filesystem::is_directory(path, error))
        throw InputError("parameter 'Output directory' = " + directory +
                         " is an existing file, not a directory");
      std::filesystem::create_directories(path, error);
      if (error || !std::filesystem::is_directory(path))
        throw InputError("parameter 'Output directory' = " + directory +
                         " cannot be created: " + (error ? error.message() : "not a directory"));
      // Probe: an empty file written and removed again.
      const auto    probe = path / (".greentread-probe." + std::to_string(::getpid()));
      std::ofstream test(probe);
      if (!test)
        throw InputError("parameter 'Output directory' = " + directory +
                         " is not writable: " + std::strerror(errno));
      test.close();
      std::filesystem::remove(probe, error);
      return path;
    }



    bool
    read_saved_stage(const std::filesystem::path &file, const std::function<void()> &read)
    {
      try
        {
          read();
          return true;
        }
      catch (const std::exception &e)
        {
          std::cout << "Not reusing " << file.string() << ", although its key matches: " << e.what()
                    << "; computing it again\n";
          return false;
        }
    }
  } // namespace base
} // namespace greentread
