// SPDX-License-Identifier: LGPL-2.1-or-later
// What every section of the parameter file shares: the exception of bad
// input, the checks that raise it with the entry's name and value, the
// choices of Selection entries as enums (parsed once where the file is
// read, so that no solver compares strings), and the reader of CSV input
// files. Each section itself is declared and parsed by the class it
// configures (material.h, interaction_law.h, indenter.h, mesh.h, ...);
// parameters.h gathers them.
#ifndef viscoslide_input_h
#define viscoslide_input_h

#include <deal.II/base/parameter_handler.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  namespace Parameters
  {
    // Bad input: the message names the entry, its value and what is
    // allowed. A plain exception, so the user sees just that sentence.
    class ExcInvalidInput : public std::runtime_error
    {
    public:
      explicit ExcInvalidInput(const std::string &message)
        : std::runtime_error(message)
      {
      }
    };

    // Throws ExcInvalidInput(message) unless condition holds.
    // Patterns::Double(lo, hi) accepts the closed interval; most of our
    // bounds are open ("a positive thickness"), so the check is ours.
    void
    require(bool condition, const std::string &message);

    // The number a word spells, or NaN if it spells none (the callers then
    // name the entry and the word).
    double
    to_number(const std::string &word);

    // A number as a message shows it.
    std::string
    num(double x);

    // "'Section/Name' = value", the start of a message about an entry.
    std::string
    entry(const std::string &section, const std::string &name, double value);

    // The words of an enum's choices, in the order of its values: declared
    // beside each enum by VISCOSLIDE_CHOICES(Enum, "word", ...).
    template <typename Choice>
    struct ChoiceNames;

#define VISCOSLIDE_CHOICES(Choice, ...)                         \
  template <>                                                   \
  struct ChoiceNames<Choice>                                    \
  {                                                             \
    static const std::vector<std::string> &                     \
    get()                                                       \
    {                                                           \
      static const std::vector<std::string> names{__VA_ARGS__}; \
      return names;                                             \
    }                                                           \
  };

    template <typename Choice>
    const std::vector<std::string> &
    choice_names()
    {
      return ChoiceNames<Choice>::get();
    }

    // The word of the parameter file, which is also what the outputs write.
    template <typename Choice>
    std::string
    to_string(const Choice choice)
    {
      return choice_names<Choice>()[static_cast<unsigned int>(choice)];
    }

    // "a|b|c", for Patterns::Selection.
    std::string
    selection_pattern(const std::vector<std::string> &names);

    template <typename Choice>
    std::string
    choice_pattern()
    {
      return selection_pattern(choice_names<Choice>());
    }

    // The position of word among names; ExcInvalidInput naming `entry`
    // otherwise.
    unsigned int
    find_choice(const std::vector<std::string> &names,
                const std::string              &word,
                const std::string              &entry);

    // The choice a word names; ExcInvalidInput naming `entry` otherwise.
    template <typename Choice>
    Choice
    parse_choice(const std::string &word, const std::string &entry)
    {
      return static_cast<Choice>(
        find_choice(choice_names<Choice>(), word, entry));
    }

    // The columns `names` of a CSV input file (a header line naming the
    // columns, then one row per line; lines starting with # are comments),
    // every entry a finite number. The messages of ExcInvalidInput start
    // with `what`, e.g. "'Material/Prony file' = spectrum.csv", and name the
    // line.
    std::vector<std::vector<double>>
    read_csv_columns(const std::string              &filename,
                     const std::vector<std::string> &names,
                     const std::string              &what);
  } // namespace Parameters
} // namespace viscoslide

#endif
