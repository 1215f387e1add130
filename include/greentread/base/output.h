#pragma once

#include <greentread/base/parameters.h>

#include <deal.II/base/data_out_base.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

/**
 * @file
 * Output files that are never left half-written, and that record the
 * parameters they came from.
 */

namespace greentread
{
  namespace base
  {
    /**
     * @brief The parameters a result came from: the program version and every
     * parameter of the stages that produced it.
     */
    struct ParameterRecord
    {
      /// "greentread 0.1.0 (abc123), scene sdof"
      std::string header;
      /// "Path = value" for every parameter that was used.
      std::vector<std::pair<std::string, std::string>> entries;

      /**
       * @brief Record the current values of the parameters whose path starts
       * with one of @p prefixes (all of them for an empty list).
       */
      static ParameterRecord
      from(const dealii::ParameterHandler &prm,
           const std::string              &scene,
           const std::vector<std::string> &prefixes = {});

      /// Write as comment lines, "# Path = value".
      void
      write_comments(std::ostream &out, const std::string &comment = "# ") const;

      /// The record as one text block (for PNG text chunks).
      std::string
      text() const;
    };

    /// deal.II's VTU flags without the date it writes by default: the same
    /// run then writes the same bytes.
    inline dealii::DataOutBase::VtkFlags
    undated_vtk_flags()
    {
      dealii::DataOutBase::VtkFlags flags;
      flags.print_date_and_time = false;
      return flags;
    }

    /**
     * @brief A file written under a temporary name in the same directory and
     * renamed to its final name by commit().
     *
     * If commit() is never reached (an exception, a crash), the destructor
     * removes the temporary file and the final name is untouched.
     */
    class AtomicFile
    {
    public:
      explicit AtomicFile(const std::filesystem::path &final_path,
                          std::ios::openmode           mode = std::ios::out);
      ~AtomicFile();

      AtomicFile(const AtomicFile &) = delete;
      AtomicFile &
      operator=(const AtomicFile &) = delete;

      /// The stream to write to.
      std::ofstream &
      stream()
      {
        return out;
      }

      /// The temporary path, for writers that need a file name.
      const std::filesystem::path &
      temporary_path() const
      {
        return tmp_path;
      }

      /**
       * @brief Flush, check for write errors, and rename to the final name.
       * @throws InputError if the file could not be written.
       */
      void
      commit();

    private:
      std::filesystem::path final_path;
      std::filesystem::path tmp_path;
      std::ofstream         out;
      bool                  committed = false;
    };

    /**
     * @brief Create @p directory if needed and check that files can be
     * written in it, before any work is done.
     * @throws InputError naming the parameter "Output directory".
     */
    std::filesystem::path
    prepare_output_directory(const std::string &directory);

    /**
     * @brief Read a saved stage whose key matched, by @p read. A file that
     * cannot be read in full (truncated, or holding a value that is not
     * finite) is not the user's error: say so on screen and return false, so
     * that the stage is computed again and the file rewritten.
     */
    bool
    read_saved_stage(const std::filesystem::path &file, const std::function<void()> &read);
  } // namespace base
} // namespace greentread
