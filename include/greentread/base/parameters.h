#pragma once

#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <string>
#include <vector>

/**
 * @file
 * Reading scenes (.prm files) and `--set` overrides into a
 * dealii::ParameterHandler, with errors a user can act on.
 *
 * Every stage declares and parses its own subsection (ASPECT style:
 * `static void declare_parameters(ParameterHandler &)` and
 * `void parse_parameters(ParameterHandler &)`); this file holds only what
 * is common to all of them.
 */

namespace greentread
{
  namespace base
  {
    /**
     * @brief A finite real number in a range whose ends may be open, closed
     * or absent, with its unit: "[a number > 0, in kg]".
     *
     * deal.II's Patterns::Double has closed bounds only, so a mass "> 0"
     * would be listed as [0, MAX_DOUBLE]; this pattern lets
     * --print-parameters and the parse errors state the true range.
     */
    class RangePattern : public dealii::Patterns::PatternBase
    {
    public:
      enum class Bound
      {
        none,
        inclusive,
        exclusive
      };

      RangePattern(double      lower,
                   Bound       lower_kind,
                   double      upper,
                   Bound       upper_kind,
                   std::string unit);

      /// x > 0
      static RangePattern
      positive(const std::string &unit);
      /// x >= 0
      static RangePattern
      non_negative(const std::string &unit);
      /// lower <= x <= upper
      static RangePattern
      closed(double lower, double upper, const std::string &unit);

      bool
      match(const std::string &test_string) const override;

      std::string
      description(OutputStyle style = Machine) const override;

      std::unique_ptr<dealii::Patterns::PatternBase>
      clone() const override;

    private:
      double      lower, upper;
      Bound       lower_kind, upper_kind;
      std::string unit;
    };

    /**
     * @brief One parameter as it stands after parsing.
     */
    struct ParameterEntry
    {
      /// Full path, subsections separated by '/': "Oscillator/Mass".
      std::string path;
      std::string value;
      std::string default_value;
      std::string documentation;
      /// What deal.II's Patterns:: object allows, in its own words.
      std::string allowed;
    };

    /// The text without its leading and trailing blanks (spaces, tabs, CR, LF).
    std::string
    trim(const std::string &s);

    /// The non-empty items of a comma-separated list, trimmed.
    std::vector<std::string>
    split_list(const std::string &text);

    /**
     * @brief Every declared parameter in declaration order.
     */
    std::vector<ParameterEntry>
    list_parameters(const dealii::ParameterHandler &prm);

    /**
     * @brief Parse a scene file into @p prm.
     *
     * @throws InputError naming the file, the line, the parameter and what is
     * allowed, with the closest declared name for a misspelled one.
     */
    void
    parse_scene_file(dealii::ParameterHandler &prm, const std::string &filename);

    /**
     * @brief Apply one command-line override "Section/Sub/Name=value".
     *
     * @throws InputError for an undeclared parameter or a value its pattern
     * rejects.
     */
    void
    apply_override(dealii::ParameterHandler &prm, const std::string &assignment);

    /**
     * @brief The same reference as Markdown, one table per subsection and the
     * deprecated spellings last: doc/parameters.md is this output
     * (`greentread --print-parameters=markdown`), and a test fails when the
     * file differs from it.
     */
    void
    print_parameter_markdown(const dealii::ParameterHandler &prm, std::ostream &out);

    /**
     * @brief Write the reference of all parameters: path, default, allowed
     * values, and documentation (which carries the unit).
     */
    void
    print_parameter_reference(const dealii::ParameterHandler &prm, std::ostream &out);

    /**
     * @brief The declared name closest to @p name (Levenshtein distance), or
     * an empty string when nothing is reasonably close.
     */
    std::string
    closest_name(const std::string &name, const std::vector<std::string> &candidates);
  } // namespace base
} // namespace greentread
