// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <viscoslide/io/input.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace viscoslide
{
  namespace Parameters
  {
    void
    require(const bool condition, const std::string &message)
    {
      if (!condition)
        throw ExcInvalidInput(message);
    }


    double
    to_number(const std::string &word)
    {
      try
        {
          return Utilities::string_to_double(word);
        }
      catch (...)
        {
          return std::numeric_limits<double>::quiet_NaN();
        }
    }


    std::string
    num(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }


    std::string
    entry(const std::string &section,
          const std::string &name,
          const double       value)
    {
      return "'" + section + "/" + name + "' = " + num(value);
    }


    std::string
    selection_pattern(const std::vector<std::string> &names)
    {
      std::string pattern;
      for (const auto &name : names)
        pattern += (pattern.empty() ? "" : "|") + name;
      return pattern;
    }


    unsigned int
    find_choice(const std::vector<std::string> &names,
                const std::string              &word,
                const std::string              &entry)
    {
      const auto i = std::find(names.begin(), names.end(), word);
      if (i == names.end())
        throw ExcInvalidInput("'" + entry + "' = " + word + " is not one of " +
                              selection_pattern(names));
      return i - names.begin();
    }


    std::vector<std::vector<double>>
    read_csv_columns(const std::string              &filename,
                     const std::vector<std::string> &names,
                     const std::string              &what)
    {
      std::ifstream in(filename);
      require(static_cast<bool>(in), what + ": cannot read the file");
      std::vector<int>                 column;
      std::vector<std::vector<double>> values(names.size());
      std::string                      line;
      for (unsigned int line_number = 1; std::getline(in, line); ++line_number)
        {
          line = Utilities::trim(line);
          if (line.empty() || line[0] == '#')
            continue;
          const auto words = Utilities::split_string_list(line, ',');
          if (column.empty())
            {
              std::string header;
              for (const auto &name : names)
                {
                  const auto i = std::find(words.begin(), words.end(), name);
                  column.push_back(i == words.end() ? -1 : i - words.begin());
                  header += (header.empty() ? "" : ", ") + name;
                }
              require(std::find(column.begin(), column.end(), -1) ==
                        column.end(),
                      what + ": the header needs the columns " + header);
              continue;
            }
          for (unsigned int c = 0; c < names.size(); ++c)
            {
              const double v = column[c] < static_cast<int>(words.size())
                                 ? to_number(words[column[c]])
                                 : std::numeric_limits<double>::quiet_NaN();
              require(std::isfinite(v),
                      what + ": no number in column " + names[c] + " of line " +
                        std::to_string(line_number));
              values[c].push_back(v);
            }
        }
      require(!column.empty(), what + ": no header line");
      return values;
    }
  } // namespace Parameters
} // namespace viscoslide
