// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <viscoslide/driver/study.h>
#include <viscoslide/io/output.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <type_traits>

namespace viscoslide
{
  namespace Study
  {
    namespace fs = std::filesystem;

    // Reads `input`, applies the case's settings, checks every entry.
    void
    read_case(const std::string &input, Case &c)
    {
      ParameterHandler prm;
      Parameters::AllParameters::declare(prm);
      prm.parse_input(input);
      for (const auto &s : c.settings)
        {
          prm.enter_subsection(s.section);
          prm.set(s.entry, s.value);
          prm.leave_subsection();
        }
      c.parameters.parse(prm);
      std::ostringstream text, json;
      prm.print_parameters(text, ParameterHandler::PRM);
      prm.print_parameters(json, ParameterHandler::JSON);
      c.parameter_text = text.str();
      c.parameter_json = json.str();
    }

    namespace
    {
      // One value of a sweep list: its part of the folder name and the
      // entries it sets.
      struct Choice
      {
        std::string          label;
        std::vector<Setting> settings;
      };


      // The non-empty lists of the Sweep section (and a transient run's
      // speeds), each a dimension of the study.
      std::vector<std::vector<Choice>>
      sweep_dimensions(const Parameters::AllParameters &p)
      {
        std::vector<std::vector<Choice>> dimensions;
        // The entries of a list as the words of a parameter file.
        auto words = [](const auto &v) {
          std::vector<std::string> w;
          for (const auto x : v)
            if constexpr (std::is_same_v<decltype(x), const double>)
              w.push_back(CsvTable::format(x));
            else
              w.push_back(Parameters::to_string(x));
          return w;
        };
        auto add = [&](const std::vector<std::string> &values,
                       const std::string              &prefix,
                       auto                          &&settings_of) {
          if (values.empty())
            return;
          std::vector<Choice> d;
          for (const auto &v : values)
            {
              // a folder name without spaces ("flat punch" -> flat-punch)
              std::string label = v == "half-plane" ? v : prefix + v;
              std::replace(label.begin(), label.end(), ' ', '-');
              d.push_back({label, settings_of(v)});
            }
          dimensions.push_back(d);
        };
        const auto &sw = p.sweep;
        add(words(sw.tabor_parameters), "muT", [](const std::string &v) {
          return std::vector<Setting>{{"Adhesion", "Tabor parameter", v}};
        });
        add(sw.thicknesses, "t", [](const std::string &v) {
          if (v == "half-plane")
            return std::vector<Setting>{{"Geometry", "Substrate", v}};
          return std::vector<Setting>{{"Geometry", "Substrate", "layer"},
                                      {"Geometry", "Layer thickness", v}};
        });
        add(words(sw.approaches), "delta", [](const std::string &v) {
          return std::vector<Setting>{{"Loading", "Final approach", v},
                                      {"Loading", "Target load", ""}};
        });
        add(words(sw.loads), "F", [](const std::string &v) {
          return std::vector<Setting>{{"Loading", "Target load", v}};
        });
        // A case runs one solver: its checks and notes are that solver's.
        add(words(sw.solvers), "", [](const std::string &v) {
          return std::vector<Setting>{{"Sliding", "Solver", v},
                                      {"Sweep", "Solvers", ""}};
        });
        add(words(sw.controls), "", [](const std::string &v) {
          return std::vector<Setting>{{"Sliding", "Control", v}};
        });
        add(words(sw.spring_stiffnesses), "k", [](const std::string &v) {
          return std::vector<Setting>{{"Sliding", "Spring stiffness", v}};
        });
        add(sw.shapes, "", [](const std::string &v) {
          return std::vector<Setting>{{"Indenter", "Shape", v}};
        });
        add(words(sw.temperatures), "T", [](const std::string &v) {
          return std::vector<Setting>{{"Units", "Temperature", v}};
        });
        if (p.sliding.solver == Parameters::SlidingSolver::transient &&
            p.sliding.speeds.size() > 1)
          add(words(p.sliding.speeds), "V", [](const std::string &v) {
            return std::vector<Setting>{{"Sliding", "Sliding speed", v}};
          });

        return dimensions;
      }
    } // namespace


    // The product of the sweep lists. A list of one entry is applied but
    // does not appear in the folder names.
    std::vector<Case>
    make_cases(const Parameters::AllParameters &p)
    {
      std::vector<Case> cases(1);
      for (const auto &d : sweep_dimensions(p))
        {
          std::vector<Case> product;
          for (const auto &c : cases)
            for (const auto &choice : d)
              {
                Case n = c;
                if (d.size() > 1)
                  n.name += (n.name.empty() ? "" : "_") + choice.label;
                n.settings.insert(n.settings.end(),
                                  choice.settings.begin(),
                                  choice.settings.end());
                product.push_back(n);
              }
          cases = product;
        }
      return cases;
    }


    bool
    read_cases(const std::string &input,
               std::vector<Case> &cases,
               fs::path          &top,
               MPI_Comm           comm)
    {
      const bool  root = Utilities::MPI::this_mpi_process(comm) == 0;
      std::string in_case;
      auto        report = [&](const auto &print) {
        if (!root)
          return;
        std::cerr << "viscoslide: error in parameter file '" << input << "'"
                  << (in_case.empty() ? "" : ", sweep case " + in_case)
                  << ":\n";
        print();
      };
      try
        {
          if (!std::ifstream(input))
            throw Parameters::ExcInvalidInput("cannot read parameter file '" +
                                              input + "'");
          Case base;
          read_case(input, base);
          cases = make_cases(base.parameters);
          top   = base.parameters.output.directory;
          for (auto &c : cases)
            {
              in_case = c.name;
              if (!c.name.empty())
                c.settings.push_back(
                  {"Output", "Output directory", (top / c.name).string()});
              read_case(input, c);
            }
        }
      catch (ExceptionBase &e) // ParameterHandler's: show only its message
        {
          report([&] { e.print_info(std::cerr); });
          return false;
        }
      catch (std::exception &e)
        {
          report([&] { std::cerr << e.what() << std::endl; });
          return false;
        }
      return true;
    }
  } // namespace Study
} // namespace viscoslide
