#include <viscoslide/indenter.h>
#include <viscoslide/parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <type_traits>

namespace viscoslide
{
  namespace Parameters
  {
    namespace
    {
      // Patterns::Double(lo, hi) accepts the closed interval; most of our
      // bounds are open ("a positive thickness"), so the check is ours.
      void
      require(const bool condition, const std::string &message)
      {
        if (!condition)
          throw ExcInvalidInput(message);
      }

      // The number a word spells, or NaN if it spells none (the callers
      // then name the entry and the word).
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

      // The choices an entry and its Sweep list share.
      const std::string shape_choices =
        "parabola|circle|flat punch|power law|sinusoid|expression|table";

      // A number as a message shows it.
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

      // A Prony term's weight and time must be positive and finite; where
      // names the list or the file row.
      PronyTerm
      prony_term(const double       weight,
                 const double       time_ratio,
                 const std::string &where)
      {
        require(std::isfinite(weight) && weight > 0,
                where + ": the weight must be a positive number");
        require(std::isfinite(time_ratio) && time_ratio > 0,
                where + ": the relaxation time must be a positive number");
        return {weight, time_ratio};
      }

      std::vector<PronyTerm>
      prony_series_from_lists(const std::string &weights,
                              const std::string &times)
      {
        const auto w = Utilities::split_string_list(weights);
        const auto t = Utilities::split_string_list(times);
        require(w.size() == t.size(),
                "'Material/Prony weights' has " + std::to_string(w.size()) +
                  " entries and 'Material/Prony relaxation times' " +
                  std::to_string(t.size()) + ": one of each per arm");
        std::vector<PronyTerm> series;
        for (unsigned int k = 0; k < w.size(); ++k)
          series.push_back(
            prony_term(to_number(w[k]),
                       to_number(t[k]),
                       "'Material/Prony weights' = " + weights +
                         ", 'Prony relaxation times' = " + times + ", arm " +
                         std::to_string(k + 1)));
        return series;
      }

      std::vector<PronyTerm>
      prony_series_from_file(const std::string &filename)
      {
        const auto columns =
          read_csv_columns(filename,
                           {"weight", "tau_over_tau"},
                           "'Material/Prony file' = " + filename);
        std::vector<PronyTerm> series;
        for (unsigned int k = 0; k < columns[0].size(); ++k)
          series.push_back(prony_term(columns[0][k],
                                      columns[1][k],
                                      "'Material/Prony file' = " + filename +
                                        ", arm " + std::to_string(k + 1)));
        require(!series.empty(),
                "'Material/Prony file' = " + filename + ": no arm in the file");
        return series;
      }
    } // namespace


#define VISCOSLIDE_CHOICE_NAMES(Choice, ...)                  \
  template <>                                                 \
  const std::vector<std::string> &choice_names<Choice>()      \
  {                                                           \
    static const std::vector<std::string> names{__VA_ARGS__}; \
    return names;                                             \
  }
    VISCOSLIDE_CHOICE_NAMES(Verbosity, "quiet", "normal", "verbose")
    VISCOSLIDE_CHOICE_NAMES(FieldFormat, "vtu", "hdf5")
    VISCOSLIDE_CHOICE_NAMES(TimeConstant, "relaxation", "retardation")
    VISCOSLIDE_CHOICE_NAMES(Substrate, "half-plane", "layer")
    VISCOSLIDE_CHOICE_NAMES(Control, "displacement", "force", "spring")
    VISCOSLIDE_CHOICE_NAMES(SlidingSolver,
                            "transient",
                            "steady-state",
                            "boundary-element")
    VISCOSLIDE_CHOICE_NAMES(LinearSolver, "automatic", "direct", "iterative")
#undef VISCOSLIDE_CHOICE_NAMES

    template <typename Choice>
    std::string
    choice_pattern()
    {
      std::string pattern;
      for (const auto &name : choice_names<Choice>())
        pattern += (pattern.empty() ? "" : "|") + name;
      return pattern;
    }

    template <typename Choice>
    Choice
    parse_choice(const std::string &word, const std::string &entry)
    {
      const auto &names = choice_names<Choice>();
      for (unsigned int k = 0; k < names.size(); ++k)
        if (names[k] == word)
          return static_cast<Choice>(k);
      throw ExcInvalidInput("'" + entry + "' = " + word + " is not one of " +
                            choice_pattern<Choice>());
    }

#define VISCOSLIDE_INSTANTIATE_CHOICE(Choice)                    \
  template std::string choice_pattern<Choice>();                 \
  template Choice      parse_choice<Choice>(const std::string &, \
                                       const std::string &);
    VISCOSLIDE_INSTANTIATE_CHOICE(Verbosity)
    VISCOSLIDE_INSTANTIATE_CHOICE(FieldFormat)
    VISCOSLIDE_INSTANTIATE_CHOICE(TimeConstant)
    VISCOSLIDE_INSTANTIATE_CHOICE(Substrate)
    VISCOSLIDE_INSTANTIATE_CHOICE(Control)
    VISCOSLIDE_INSTANTIATE_CHOICE(SlidingSolver)
    VISCOSLIDE_INSTANTIATE_CHOICE(LinearSolver)
#undef VISCOSLIDE_INSTANTIATE_CHOICE


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


    void
    Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory that receives every file of the run: "
                        "approach.csv, surface profiles, VTU/PVTU fields with "
                        "their .pvd collection, and the parameter set "
                        "actually used (parameters.prm, parameters.json). "
                        "An existing directory that already holds results "
                        "is refused unless the program is called with "
                        "--overwrite.");
      prm.declare_entry("Verbosity",
                        "normal",
                        Patterns::Selection(choice_pattern<Verbosity>()),
                        "'quiet': only the start and end of each case and "
                        "errors. 'normal': one line per step (approach) or "
                        "per speed (steady-state solver) with the progress "
                        "of the run: case k of n, sliding distance covered, "
                        "elapsed and estimated remaining time. 'verbose': "
                        "also every Newton residual and line-search step.");
      prm.declare_entry("Write fields",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVTU volume and surface fields.");
      prm.declare_entry(
        "Field format",
        "vtu",
        Patterns::Selection(choice_pattern<FieldFormat>()),
        "'vtu': per step one .vtu per process and a .pvtu, listed in NAME.pvd "
        "(ParaView, VisIt). 'hdf5': per step one NAME_NNNNN.h5 written "
        "by all processes together (MPI-IO), listed in NAME.xdmf (ParaView, "
        "VisIt); fewer files for large runs on many processes.");
      prm.declare_entry("Fields every",
                        "10",
                        Patterns::Integer(0),
                        "Write fields every this many accepted steps (and "
                        "always after the last step). 0: only the last.");
      prm.declare_entry("Surface profile every",
                        "0",
                        Patterns::Integer(0),
                        "Write the surface profile CSV every this many "
                        "accepted steps (and always after the last step). "
                        "0: only the last.");
      prm.declare_entry(
        "Checkpoint every",
        "100",
        Patterns::Integer(0),
        "Transient sliding: write a checkpoint (mesh, solution, history, "
        "sliding position and steady-state window) into OUTPUT/checkpoint "
        "every this many sliding steps, so that `viscoslide --resume` "
        "continues a killed run from there (doc/restart.md). The "
        "steady-state solver writes one after every converged speed or load "
        "whatever the value above 0. The previous checkpoint is replaced "
        "only once the new one is complete. 0: none.");
      prm.leave_subsection();
    }

    void
    Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Output directory");
      verbosity =
        parse_choice<Verbosity>(prm.get("Verbosity"), "Output/Verbosity");
      write_fields     = prm.get_bool("Write fields");
      fields_every     = prm.get_integer("Fields every");
      field_format     = parse_choice<FieldFormat>(prm.get("Field format"),
                                               "Output/Field format");
      profile_every    = prm.get_integer("Surface profile every");
      checkpoint_every = prm.get_integer("Checkpoint every");
      prm.leave_subsection();
      require(!directory.empty(),
              "'Output/Output directory' must not be empty");
    }


    void
    Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("E0 over Einf",
                        "0.1",
                        Patterns::Double(),
                        "Ratio of the relaxed (low-frequency) to the "
                        "instantaneous (high-frequency) Young's modulus of "
                        "the standard linear solid, in (0, 1]. 1 makes the "
                        "material elastic. Einf < E0 is unphysical and "
                        "refused.");
      prm.declare_entry("Poisson ratio",
                        "0.49",
                        Patterns::Double(),
                        "Poisson ratio, the same for both branches, in "
                        "[0, 0.5).");
      prm.declare_entry(
        "Time constant",
        "relaxation",
        Patterns::Selection(choice_pattern<TimeConstant>()),
        "Which time constant tau makes V_hat = V tau/eps and time_over_tau "
        "dimensionless. 'relaxation': tau is the relaxation time of the "
        "Maxwell arm, E(t) = E0 + (Einf - E0) exp(-t/tau) (the paper's "
        "wording). 'retardation': tau is the creep (retardation) time "
        "tau_c = tau_relaxation Einf/E0 of J(t) = 1/E0 - (1/E0 - 1/Einf) "
        "exp(-t/tau_c). The choice is written into every output file.");
      prm.declare_entry(
        "Prony weights",
        "",
        Patterns::Anything(),
        "Generalised Maxwell solid (Prony series): a comma-separated list of "
        "positive weights w_k, one per Maxwell arm. Arm k carries the "
        "modulus E_k = w_k (Einf - E0) / sum(w), so 'E0 over Einf' still "
        "fixes the slow and fast limits and the weights only share out "
        "Einf - E0; measured moduli E_k (in any unit) may be given as they "
        "are. Empty (default): one arm, the standard linear solid of the "
        "paper. Needs 'Prony relaxation times' of the same length; not "
        "together with 'Prony file'.");
      prm.declare_entry(
        "Prony relaxation times",
        "",
        Patterns::Anything(),
        "The relaxation times tau_k/tau of the arms of 'Prony weights', "
        "positive, in units of the reference time tau of V_hat and "
        "time_over_tau. E(t) = E0 + sum_k E_k exp(-t/tau_k).");
      prm.declare_entry(
        "Prony file",
        "",
        Patterns::Anything(),
        "The Prony series as a CSV file (path relative to the working "
        "directory; lines starting with # are comments) with a header "
        "naming the columns weight and tau_over_tau, one arm per row: a "
        "measured relaxation spectrum (weights as 'Prony weights', times "
        "as 'Prony relaxation times'). Empty: the lists above.");
      prm.leave_subsection();
    }

    void
    Material::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      E0_over_Einf  = prm.get_double("E0 over Einf");
      poisson_ratio = prm.get_double("Poisson ratio");
      time_constant = parse_choice<TimeConstant>(prm.get("Time constant"),
                                                 "Material/Time constant");
      const std::string weights = prm.get("Prony weights"),
                        times   = prm.get("Prony relaxation times"),
                        file    = prm.get("Prony file");
      prm.leave_subsection();
      require(file.empty() || (weights.empty() && times.empty()),
              "'Material/Prony file' and 'Material/Prony weights' or "
              "'Material/Prony relaxation times' are both set: give the "
              "series one way");
      prony_series = file.empty() ? prony_series_from_lists(weights, times)
                                  : prony_series_from_file(file);
      require(prony_series.size() <= 1 ||
                time_constant == TimeConstant::relaxation,
              "'Material/Time constant' = retardation is defined for one "
              "Maxwell arm only; a Prony series needs relaxation");
      require(E0_over_Einf > 0 && E0_over_Einf <= 1,
              entry("Material", "E0 over Einf", E0_over_Einf) +
                " is outside (0, 1]: Einf must not be smaller than E0");
      require(poisson_ratio >= 0 && poisson_ratio < 0.5,
              entry("Material", "Poisson ratio", poisson_ratio) +
                " is outside [0, 0.5)");
    }


    void
    Adhesion::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Adhesion");
      prm.declare_entry("Interaction law",
                        "lennard-jones",
                        Patterns::Selection(
                          "lennard-jones|repulsive|exponential|dugdale"),
                        "Surface traction-gap law on the top boundary, each "
                        "with work of separation dgamma (doc/model.md). "
                        "'lennard-jones': the 3-9 law of doc/model.md. "
                        "'repulsive': only its repulsive branch (g < eps), "
                        "rounded to zero slope over [0.98 eps, eps] so that "
                        "Newton converges, i.e. frictionless contact "
                        "without adhesion. 'exponential': Xu-Needleman's "
                        "normal law about the gap eps, with the "
                        "Lennard-Jones peak traction. 'dugdale': "
                        "Maugis-Dugdale, the Lennard-Jones peak traction "
                        "constant over the range dgamma/sigma_max beyond "
                        "the repulsive wall, its ends smoothed over 5 % of "
                        "the range.");
      prm.declare_entry("Tabor parameter",
                        "6.08",
                        Patterns::Double(),
                        "muT = (R dgamma^2/(E0*^2 eps^3))^(1/3), computed with "
                        "the relaxed modulus. 1: long-range, 6.08: "
                        "short-range adhesion (the paper's two cases). With "
                        "'repulsive' it only sets the stiffness of the "
                        "repulsive wall.");
      prm.declare_entry("R over eps",
                        "1e4",
                        Patterns::Double(),
                        "Indenter radius R_hat = R/eps. The paper does not "
                        "state it; with 1e4, dgamma/(E0* eps) = 0.15 at "
                        "muT = 6.08. F_hat, delta_hat and p_hat do not "
                        "depend on it; V_hat, L_hat and mu scale with "
                        "sqrt(R_hat).");
      prm.declare_entry("Contact gap threshold",
                        "1.2",
                        Patterns::Double(),
                        "A surface point is in contact where the gap is "
                        "below this many eps (the paper uses 1.2, the "
                        "position of the Lennard-Jones peak traction).");
      prm.declare_entry("Face quadrature points",
                        "5",
                        Patterns::Integer(2, 12),
                        "Gauss points per top face for the adhesion "
                        "integral.");
      prm.leave_subsection();
    }

    void
    Adhesion::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Adhesion");
      law                    = prm.get("Interaction law");
      tabor_parameter        = prm.get_double("Tabor parameter");
      R_over_eps             = prm.get_double("R over eps");
      contact_gap            = prm.get_double("Contact gap threshold");
      face_quadrature_points = prm.get_integer("Face quadrature points");
      prm.leave_subsection();
      require(tabor_parameter > 0 && std::isfinite(tabor_parameter),
              entry("Adhesion", "Tabor parameter", tabor_parameter) +
                " must be positive");
      require(R_over_eps >= 10 && std::isfinite(R_over_eps),
              entry("Adhesion", "R over eps", R_over_eps) +
                " must be at least 10 (Derjaguin approximation)");
      require(contact_gap > 1,
              entry("Adhesion", "Contact gap threshold", contact_gap) +
                " must exceed 1 (the equilibrium gap)");
    }


    void
    IndenterProfile::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Indenter");
      prm.declare_entry(
        "Shape",
        "parabola",
        Patterns::Selection(shape_choices),
        "The rigid profile h(x) above its lowest point, x from the apex and "
        "h in eps; the approach delta is measured from h = 0 (doc/model.md). "
        "'parabola': x^2/(2R), the paper's cylinder. 'circle': the exact "
        "circle R - sqrt(R^2 - x^2). 'flat punch': flat over |x| <= Punch "
        "half-width, corners rounded by parabolas of Corner radius. "
        "'power law': |x|^n/(n R^(n-1)) with n = Exponent (2: the "
        "parabola). 'sinusoid': Amplitude (1 - cos(2 pi x/Wavelength)), "
        "periodic. 'expression': the muParser Expression. 'table': the CSV "
        "Profile file. R is 'Adhesion/R over eps' for every shape, so the "
        "Tabor parameter, F_hat, V_hat and L_hat keep the paper's "
        "normalisation whatever the shape.");
      prm.declare_entry("Punch half-width",
                        "100",
                        Patterns::Double(),
                        "Flat punch: half-width b of the flat part, in eps.");
      prm.declare_entry("Corner radius",
                        "1000",
                        Patterns::Double(),
                        "Flat punch: radius r of the parabolic corners "
                        "(h = (|x| - b)^2/(2r) beyond b), in eps; it keeps "
                        "the edge pressure finite. Resolve it: the corner "
                        "contact (a - b) should span several finest cells.");
      prm.declare_entry("Exponent",
                        "2",
                        Patterns::Double(),
                        "Power law: n >= 1 (1: a wedge, 2: the parabola).");
      prm.declare_entry("Amplitude",
                        "10",
                        Patterns::Double(),
                        "Sinusoid: amplitude A in eps (peak to valley 2A).");
      prm.declare_entry("Wavelength",
                        "2000",
                        Patterns::Double(),
                        "Sinusoid: wavelength in eps; the apex radius of "
                        "curvature is Wavelength^2/(4 pi^2 A).");
      prm.declare_entry("Expression",
                        "x^2/(2*R)",
                        Patterns::Anything(),
                        "Expression: h as a muParser function of x (both in "
                        "eps), with the constants R (= R_hat) and pi, e.g. "
                        "'x^2/(2*R) + 1e-7*x^4'. Its slope is taken by "
                        "central differences of 1e-6 eps.");
      prm.declare_entry("Profile file",
                        "",
                        Patterns::Anything(),
                        "Table: a CSV file (path relative to the working "
                        "directory) with a header naming the columns "
                        "x_over_eps and h_over_eps, x increasing; '#' lines "
                        "are comments. h is interpolated linearly and "
                        "continues flat beyond the ends, so the table "
                        "should cover the contact and the sliding "
                        "distance. The file is read when the parameters "
                        "are, and a changed file is not detected by "
                        "--resume.");
      prm.leave_subsection();
    }

    void
    IndenterProfile::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Indenter");
      shape         = prm.get("Shape");
      half_width    = prm.get_double("Punch half-width");
      corner_radius = prm.get_double("Corner radius");
      exponent      = prm.get_double("Exponent");
      amplitude     = prm.get_double("Amplitude");
      wavelength    = prm.get_double("Wavelength");
      expression    = prm.get("Expression");
      profile_file  = prm.get("Profile file");
      prm.leave_subsection();
      const auto positive = [](const char *name, const double v) {
        require(v > 0 && std::isfinite(v),
                entry("Indenter", name, v) + " must be positive");
      };
      if (shape == "flat punch")
        {
          require(half_width >= 0 && std::isfinite(half_width),
                  entry("Indenter", "Punch half-width", half_width) +
                    " must be zero or positive");
          positive("Corner radius", corner_radius);
        }
      if (shape == "power law")
        require(exponent >= 1 && std::isfinite(exponent),
                entry("Indenter", "Exponent", exponent) +
                  " must be at least 1 (a finite slope at the apex)");
      if (shape == "sinusoid")
        {
          positive("Amplitude", amplitude);
          positive("Wavelength", wavelength);
        }
      require(shape != "table" || !profile_file.empty(),
              "'Indenter/Shape' = table needs a 'Indenter/Profile file'");
    }


    void
    Geometry::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Substrate",
                        "half-plane",
                        Patterns::Selection(choice_pattern<Substrate>()),
                        "'half-plane': a block of Domain width x Domain "
                        "height, large against the contact, base fixed. "
                        "'layer': a layer of Layer thickness bonded to a "
                        "rigid base.");
      prm.declare_entry("Layer thickness",
                        "100",
                        Patterns::Double(),
                        "t_hat = t/eps, used with Substrate = layer.");
      prm.declare_entry("Domain width",
                        "20000",
                        Patterns::Double(),
                        "W/eps, the lateral extent of the block (x from "
                        "-W/2 to W/2). Lateral sides are traction free.");
      prm.declare_entry("Domain height",
                        "10000",
                        Patterns::Double(),
                        "H/eps of the half-plane block. Under displacement "
                        "control the approach delta depends on it "
                        "logarithmically (plane strain).");
      prm.declare_entry(
        "Wake lengths",
        "20",
        Patterns::Double(0.),
        "The steady-state solver needs the wake, the solid relaxing "
        "over V tau_c behind the contact (tau_c the creep time), inside "
        "its block, or it underestimates the friction at high speed. "
        "Under force control it widens the block to at least this many "
        "wake lengths of the fastest listed speed and deepens a "
        "half-plane to a quarter of that; the boundary elements approach "
        "on the same depth. Under displacement and spring control the "
        "block stays as given (it sets the reference of delta) and a "
        "warning says when it is too small; a layer is widened under "
        "every control. Set 0 to keep Domain width and height as given, "
        "for example for a periodic profile whose wavelength is the "
        "width, or with Mesh/Uniform surface (which keeps them anyway).");
      prm.leave_subsection();
    }

    void
    Geometry::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      substrate =
        parse_choice<Substrate>(prm.get("Substrate"), "Geometry/Substrate");
      layer_thickness = prm.get_double("Layer thickness");
      domain_width    = prm.get_double("Domain width");
      domain_height   = prm.get_double("Domain height");
      wake_lengths    = prm.get_double("Wake lengths");
      prm.leave_subsection();
      require(layer_thickness > 0 && std::isfinite(layer_thickness),
              entry("Geometry", "Layer thickness", layer_thickness) +
                " must be positive");
      require(domain_width > 0 && std::isfinite(domain_width),
              entry("Geometry", "Domain width", domain_width) +
                " must be positive");
      require(domain_height > 0 && std::isfinite(domain_height),
              entry("Geometry", "Domain height", domain_height) +
                " must be positive");
    }


    void
    Loading::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      prm.declare_entry("Initial approach",
                        "-2",
                        Patterns::Double(),
                        "delta_hat at the start: the apex is at a gap of "
                        "1 - delta_hat eps from the undeformed surface.");
      prm.declare_entry("Final approach",
                        "3",
                        Patterns::Double(),
                        "delta_hat reached at the end of the approach "
                        "(displacement control).");
      prm.declare_entry("Approach increment",
                        "0.1",
                        Patterns::Double(),
                        "Increment of delta_hat per step. Steps are halved "
                        "automatically when Newton fails.");
      prm.declare_entry("Minimum increment",
                        "1e-3",
                        Patterns::Double(),
                        "Smallest increment step cutting may reach; below it "
                        "a surface instability (jump-in, jump-out) is "
                        "assumed and the new branch is found by damped "
                        "relaxation.");
      prm.declare_entry("Approach speed",
                        "0",
                        Patterns::Double(),
                        "Normal speed V_n tau/eps. 0 means quasi-static: "
                        "every step is fully relaxed (modulus E0).");
      prm.declare_entry("Hold time",
                        "0",
                        Patterns::Double(),
                        "After the approach, hold delta for this time "
                        "(in tau) while the material relaxes.");
      prm.declare_entry("Hold steps",
                        "20",
                        Patterns::Integer(1),
                        "Time steps of the hold, spaced geometrically from "
                        "1e-3 tau so that the relaxation is resolved.");
      prm.declare_entry(
        "Target load",
        "",
        Patterns::Anything(),
        "F_hat to reach instead of Final approach: the approach goes on "
        "in steps of Approach increment until F_n passes this value (after "
        "contact is made), and that step is then solved with F_n held at "
        "exactly this load. Negative values are tensile loads; they must "
        "lie above the pull-off force. Final approach then only bounds the "
        "search. Empty: no target, the approach ends at Final approach.");
      prm.declare_entry("Retract",
                        "false",
                        Patterns::Bool(),
                        "After approach (and hold) retract to Retract to, "
                        "completing a loading-unloading cycle; the minimum "
                        "force on the way is the pull-off force. Without "
                        "sliding (Sliding speed = 0) with every solver; "
                        "the boundary elements retract quasi-statically.");
      prm.declare_entry("Retract to",
                        "-3",
                        Patterns::Double(),
                        "delta_hat at the end of the retraction.");
      prm.leave_subsection();
    }

    void
    Loading::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      initial_approach       = prm.get_double("Initial approach");
      final_approach         = prm.get_double("Final approach");
      increment              = prm.get_double("Approach increment");
      minimum_increment      = prm.get_double("Minimum increment");
      approach_speed         = prm.get_double("Approach speed");
      hold_time              = prm.get_double("Hold time");
      hold_steps             = prm.get_integer("Hold steps");
      retract                = prm.get_bool("Retract");
      retract_to             = prm.get_double("Retract to");
      const std::string load = prm.get("Target load");
      prm.leave_subsection();
      target_load = std::numeric_limits<double>::quiet_NaN();
      if (!dealii::Utilities::trim(load).empty())
        {
          target_load = to_number(load);
          require(std::isfinite(target_load),
                  "'Loading/Target load' = " + load +
                    " is not a finite number");
        }
      require(increment > 0,
              entry("Loading", "Approach increment", increment) +
                " must be positive");
      require(minimum_increment > 0 && minimum_increment <= increment,
              entry("Loading", "Minimum increment", minimum_increment) +
                " must be positive and not above the Approach increment");
      require(approach_speed >= 0,
              entry("Loading", "Approach speed", approach_speed) +
                " must not be negative");
      require(hold_time >= 0,
              entry("Loading", "Hold time", hold_time) +
                " must not be negative");
      require(final_approach >= initial_approach,
              entry("Loading", "Final approach", final_approach) +
                " is below the Initial approach");
      require(!retract || retract_to < final_approach,
              entry("Loading", "Retract to", retract_to) +
                " must be below the Final approach");
    }


    void
    Mesh::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry("Finest surface cell",
                        "0.5",
                        Patterns::Double(),
                        "Size (in eps) of the finest cells, placed at the "
                        "contact edges. The Lennard-Jones process zone is "
                        "about 0.05 sqrt(R eps) at muT = 6.08 and must be "
                        "resolved by several such cells.");
      prm.declare_entry("Mesh grading",
                        "0.25",
                        Patterns::Double(),
                        "Away from the contact edges the desired cell size "
                        "grows as grading x distance to the nearest edge.");
      prm.declare_entry("Edge gap lower",
                        "1.05",
                        Patterns::Double(),
                        "A top face belongs to a contact edge where its gap "
                        "range overlaps [lower, upper] (in eps).");
      prm.declare_entry("Edge gap upper",
                        "2.5",
                        Patterns::Double(),
                        "See Edge gap lower.");
      prm.declare_entry(
        "Edge margin",
        "8",
        Patterns::Double(0),
        "Distance (in eps) by which a contact edge may move before the "
        "mesh is adapted again: the mesh is refined as if each edge were "
        "this much wider, and changed only where a cell is coarser than "
        "the edge itself needs. Wider "
        "margins mean fewer adaptations, each re-solve, factorization "
        "and transfer saved, for a few more cells.");
      prm.declare_entry("Adaptation cycles per step",
                        "3",
                        Patterns::Integer(0),
                        "How often a step may be re-solved on a mesh adapted "
                        "to its own solution. 0 freezes the initial mesh.");
      prm.declare_entry("Uniform surface",
                        "false",
                        Patterns::Bool(),
                        "Refine the whole top surface to the finest cell "
                        "(grading with depth only) instead of following the "
                        "contact edges: the reference for checking the "
                        "adaptive mesh, at a much higher cost.");
      prm.leave_subsection();
    }

    void
    Mesh::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      finest_cell           = prm.get_double("Finest surface cell");
      grading               = prm.get_double("Mesh grading");
      edge_gap_low          = prm.get_double("Edge gap lower");
      edge_gap_high         = prm.get_double("Edge gap upper");
      edge_margin           = prm.get_double("Edge margin");
      max_adaptation_cycles = prm.get_integer("Adaptation cycles per step");
      uniform_surface       = prm.get_bool("Uniform surface");
      prm.leave_subsection();
      require(finest_cell > 0,
              entry("Mesh", "Finest surface cell", finest_cell) +
                " must be positive");
      require(grading > 0 && grading <= 2,
              entry("Mesh", "Mesh grading", grading) + " must be in (0, 2]");
      require(edge_gap_high > edge_gap_low,
              entry("Mesh", "Edge gap upper", edge_gap_high) +
                " must exceed Edge gap lower");
    }


    void
    Sliding::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Sliding");
      prm.declare_entry(
        "Sliding speed",
        "0",
        Patterns::List(Patterns::Double(), 1),
        "V_hat = V tau/eps of the sliding phase that follows the approach "
        "(and hold); the indenter profile moves towards +x over the fixed "
        "surface. 0: no sliding. A comma-separated list of positive "
        "speeds is a sweep: the steady-state solver visits them in the "
        "order given by one continuation (each speed starts from the "
        "solution of the one before), the transient solver runs each as a "
        "case of its own; either way one row per speed in "
        "steady_state.csv.");
      prm.declare_entry(
        "Control",
        "displacement",
        Patterns::Selection(choice_pattern<Control>()),
        "'displacement': delta stays at its value after the approach and Fn "
        "is an output. 'force': Fn stays at the value reached at the end of "
        "the approach and delta is an unknown solved with the displacements. "
        "'spring': the indenter hangs on a vertical spring of stiffness "
        "Spring stiffness whose far end stays where it was at the end of "
        "the approach, so Fn = F0 + k (delta0 - delta) with F0, delta0 "
        "those of the approach; between force control (k -> 0) and "
        "displacement control (k -> infinity), like a real tribometer.");
      prm.declare_entry(
        "Spring stiffness",
        "1",
        Patterns::Double(),
        "Control = spring: k_hat = dF_hat/d delta_hat, the spring's force "
        "(per unit length, in (pi dgamma^2 E0* R)^(1/3)) per eps of "
        "approach. For scale: the contact's own stiffness dF_hat/d "
        "delta_hat is about 0.35 at muT = 1, R_hat = 1e4, F_hat = 1.");
      prm.declare_entry("Sliding increment",
                        "1",
                        Patterns::Double(),
                        "Sliding distance per time step, in finest surface "
                        "cells (Mesh/Finest surface cell); dt = increment/V.");
      prm.declare_entry(
        "Maximum sliding distance",
        "0",
        Patterns::Double(),
        "Stop sliding after this distance (in eps) even "
        "without steady state (then steady = 0). 0: "
        "automatic, 4 L + 30 min(V tau_c, 4 L) with L the "
        "contact length after the approach and tau_c the "
        "retardation time; refused if the indenter would come closer "
        "than 2 L to the lateral boundary.");
      prm.declare_entry(
        "Steady-state tolerance",
        "1e-3",
        Patterns::Double(),
        "Steady state: the means of Fn (or delta under force control), Ft "
        "and L_hat over the two halves of the last Steady-state window of "
        "sliding differ by less than this, relative to their magnitude (Ft: "
        "to max(|Ft|, 1e-3 |Fn|)). The steady values in steady_state.csv "
        "are the means over that window: with adhesion the contact edges "
        "jump from node to node and Ft flickers about its mean.");
      prm.declare_entry("Steady-state window",
                        "0",
                        Patterns::Double(),
                        "Sliding distance (eps) over which steady state is "
                        "judged and its values averaged. 0: automatic, "
                        "max(L, 2 min(V tau_c, 4 L)); the cap at 4 L can "
                        "accept a state a few % from steady when V tau_c "
                        "is much longer than L (doc/steady_state.md): set "
                        "V tau_c or more for 1 %.");
      prm.declare_entry(
        "Solver",
        "transient",
        Patterns::Selection(choice_pattern<SlidingSolver>()),
        "'transient': the moving-profile time stepping of the paper until "
        "steady state. 'steady-state': the steady sliding state solved "
        "directly in the frame of the indenter (doc/steady_state.md), with "
        "continuation in V_hat from the relaxed state of the approach; "
        "no history.csv, no retraction afterwards. 'boundary-element': the "
        "same steady states of a periodic half-plane or bonded layer from "
        "the surface compliance alone, applied by FFT on a uniform grid "
        "(doc/boundary_element.md, section Boundary element): no mesh, "
        "no fields, an independent check of the finite elements.");
      prm.declare_entry("Continuation factor",
                        "4",
                        Patterns::Double(),
                        "Steady-state solver: largest ratio between two "
                        "successive speeds of the continuation from the "
                        "relaxed state to Sliding speed (halved in log "
                        "scale when Newton fails). It starts at the speed "
                        "whose relaxation length V tau is a tenth of the "
                        "finest surface cell.");
      prm.declare_entry("Viscous strain degree",
                        "1",
                        Patterns::Integer(),
                        "Steady-state solver: polynomial degree of the "
                        "discontinuous viscous strain field (FE_DGQ). The "
                        "arm sees the L2 projection of eps(u) onto this "
                        "space (doc/steady_state.md); 1 agrees with 2 to "
                        "0.03 % in mu in the Hunter test at a fifth of the "
                        "cost.");
      prm.declare_entry(
        "Load path",
        "",
        Patterns::List(Patterns::Anything(), 0),
        "Steady-state solver: after the last listed speed, follow the "
        "steady state at that speed through these loads, in the order "
        "given, by continuation (each from the solution of the one before, "
        "in steps halved where Newton fails): F_hat values under force "
        "control (spring control: the spring's force at the approach's "
        "delta), delta_hat values under displacement control. One row per "
        "load in steady_state.csv, after the speeds' rows. Follows a "
        "branch, e.g. a sliding contact unloaded towards pull-off. Empty: "
        "none.");
      prm.leave_subsection();
    }

    void
    Sliding::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Sliding");
      const std::string speed_list = prm.get("Sliding speed");
      speeds.clear();
      for (const auto &v : dealii::Utilities::split_string_list(speed_list))
        {
          const double V = dealii::Utilities::string_to_double(v);
          require(V >= 0 && std::isfinite(V),
                  entry("Sliding", "Sliding speed", V) +
                    " must not be negative");
          speeds.push_back(V);
        }
      speed   = speeds.back();
      control = parse_choice<Control>(prm.get("Control"), "Sliding/Control");
      spring_stiffness = prm.get_double("Spring stiffness");
      increment        = prm.get_double("Sliding increment");
      max_distance     = prm.get_double("Maximum sliding distance");
      steady_tolerance = prm.get_double("Steady-state tolerance");
      steady_window    = prm.get_double("Steady-state window");
      solver = parse_choice<SlidingSolver>(prm.get("Solver"), "Sliding/Solver");
      continuation_factor   = prm.get_double("Continuation factor");
      viscous_strain_degree = prm.get_integer("Viscous strain degree");
      load_path.clear();
      for (const auto &w : Utilities::split_string_list(prm.get("Load path")))
        {
          const double value = to_number(w);
          require(std::isfinite(value),
                  "'Sliding/Load path' = " + prm.get("Load path") + ": '" + w +
                    "' is not a finite number");
          load_path.push_back(value);
        }
      prm.leave_subsection();
      require(load_path.empty() || solver == SlidingSolver::steady_state,
              "'Sliding/Load path' needs 'Sliding/Solver' = steady-state "
              "(the transient solver holds the load of the approach)");
      require(load_path.empty() || speed > 0,
              "'Sliding/Load path' needs a positive 'Sliding/Sliding "
              "speed' to follow the loads at");
      require(continuation_factor > 1 && std::isfinite(continuation_factor),
              entry("Sliding", "Continuation factor", continuation_factor) +
                " must be larger than 1");
      require(viscous_strain_degree >= 0 && viscous_strain_degree <= 4,
              entry("Sliding", "Viscous strain degree", viscous_strain_degree) +
                " must be between 0 and 4");
      require(speeds.size() == 1 ||
                *std::min_element(speeds.begin(), speeds.end()) > 0,
              "'Sliding/Sliding speed' = " + speed_list +
                ": a list of speeds must hold positive speeds only");
      require(spring_stiffness > 0 && std::isfinite(spring_stiffness),
              entry("Sliding", "Spring stiffness", spring_stiffness) +
                " must be positive");
      require(increment > 0,
              entry("Sliding", "Sliding increment", increment) +
                " must be positive");
      require(max_distance >= 0,
              entry("Sliding", "Maximum sliding distance", max_distance) +
                " must not be negative");
      require(steady_tolerance > 0,
              entry("Sliding", "Steady-state tolerance", steady_tolerance) +
                " must be positive");
      require(steady_window >= 0,
              entry("Sliding", "Steady-state window", steady_window) +
                " must not be negative");
    }


    void
    BoundaryElement::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      prm.declare_entry("Grid spacing",
                        "0",
                        Patterns::Double(),
                        "Spacing (in eps) of the uniform surface grid of "
                        "Sliding/Solver = boundary-element. 0: half the "
                        "Mesh/Finest surface cell, the node spacing of the "
                        "finite elements' quadratic surface cells there.");
      prm.declare_entry(
        "Period",
        "0",
        Patterns::Double(),
        "Length (in eps) of the periodic cell of the boundary-element "
        "solver: one indenter per period. 0: automatic, the larger of "
        "Geometry/Domain width and Wake periods x V tau_c at each speed "
        "(tau_c the longest retardation time), so that the wake has "
        "relaxed before it reaches the next indenter.");
      prm.declare_entry("Wake periods",
                        "20",
                        Patterns::Double(),
                        "See Period.");
      prm.leave_subsection();
    }

    void
    BoundaryElement::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      grid_spacing = prm.get_double("Grid spacing");
      period       = prm.get_double("Period");
      wake_periods = prm.get_double("Wake periods");
      prm.leave_subsection();
      require(grid_spacing >= 0 && std::isfinite(grid_spacing),
              entry("Boundary element", "Grid spacing", grid_spacing) +
                " must not be negative");
      require(period >= 0 && std::isfinite(period),
              entry("Boundary element", "Period", period) +
                " must not be negative");
      require(wake_periods > 0 && std::isfinite(wake_periods),
              entry("Boundary element", "Wake periods", wake_periods) +
                " must be positive");
    }


    void
    Solver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      prm.declare_entry("Linear solver",
                        "automatic",
                        Patterns::Selection(choice_pattern<LinearSolver>()),
                        "'direct': MUMPS, one factorization per bulk operator, "
                        "through which every Newton system is solved exactly "
                        "(doc/model.md, Linear solver). "
                        "'iterative': GMRES with algebraic multigrid (ML). "
                        "'automatic': direct up to Direct solver limit "
                        "unknowns, iterative above.");
      prm.declare_entry("Direct solver limit",
                        "500000",
                        Patterns::Integer(1),
                        "See Linear solver.");
      prm.declare_entry("Newton tolerance",
                        "1e-9",
                        Patterns::Double(),
                        "Newton converges when the residual norm falls "
                        "below this times the total absolute surface "
                        "traction (plus one finest cell loaded with "
                        "sigma_max).");
      prm.declare_entry("Maximum Newton iterations",
                        "25",
                        Patterns::Integer(1),
                        "Newton iterations before the step is cut.");
      prm.declare_entry("Line search",
                        "true",
                        Patterns::Bool(),
                        "Backtracking line search on the residual norm.");
      prm.declare_entry("Maximum relaxation steps",
                        "400",
                        Patterns::Integer(1),
                        "Pseudo-time steps allowed to land on a new branch "
                        "after a surface instability.");
      prm.leave_subsection();
    }

    void
    Solver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      linear_solver       = parse_choice<LinearSolver>(prm.get("Linear solver"),
                                                 "Solver/Linear solver");
      direct_solver_limit = prm.get_integer("Direct solver limit");
      newton_tolerance    = prm.get_double("Newton tolerance");
      max_newton_iterations = prm.get_integer("Maximum Newton iterations");
      line_search           = prm.get_bool("Line search");
      max_relaxation_steps  = prm.get_integer("Maximum relaxation steps");
      prm.leave_subsection();
      require(newton_tolerance > 0 && newton_tolerance < 1,
              entry("Solver", "Newton tolerance", newton_tolerance) +
                " must be in (0, 1)");
    }


    void
    Sweep::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      const auto list = Patterns::List(Patterns::Anything(), 0);
      prm.declare_entry(
        "Tabor parameters",
        "",
        list,
        "Comma-separated muT values; each replaces Adhesion/Tabor "
        "parameter in its own cases. The driver runs the product of all "
        "non-empty lists of this section (and of the speeds of a transient "
        "run), each case in its own folder of the Output directory, and "
        "collects one row per case and speed in the sweep's "
        "steady_state.csv (doc/sweeps.md). Empty: no sweep over muT.");
      prm.declare_entry("Layer thicknesses",
                        "",
                        list,
                        "Comma-separated t_hat values and/or 'half-plane'; "
                        "each replaces Geometry/Substrate and Layer "
                        "thickness in its own cases.");
      prm.declare_entry("Approaches",
                        "",
                        list,
                        "Comma-separated delta_hat values; each replaces "
                        "Loading/Final approach. Not together with Loads.");
      prm.declare_entry("Loads",
                        "",
                        list,
                        "Comma-separated F_hat values; each becomes "
                        "Loading/Target load. Not together with Approaches.");
      prm.declare_entry(
        "Controls",
        "",
        Patterns::List(Patterns::Selection(choice_pattern<Control>()), 0),
        "Comma-separated 'displacement', 'force' and/or 'spring'; "
        "each replaces Sliding/Control.");
      prm.declare_entry(
        "Solvers",
        "",
        Patterns::List(Patterns::Selection(choice_pattern<SlidingSolver>()), 0),
        "Comma-separated sliding solvers ('transient', 'steady-state', "
        "'boundary-element'); each replaces Sliding/Solver, so that one "
        "file compares the methods on the same cases.");
      prm.declare_entry("Spring stiffnesses",
                        "",
                        list,
                        "Comma-separated k_hat values; each replaces "
                        "Sliding/Spring stiffness (used where Control is "
                        "spring).");
      prm.declare_entry(
        "Indenter shapes",
        "",
        Patterns::List(Patterns::Selection(shape_choices), 0),
        "Comma-separated shapes; each replaces Indenter/Shape (the other "
        "Indenter entries apply to the shape that uses them). Case folders "
        "are named by the shape with '-' for spaces.");
      prm.leave_subsection();
    }

    void
    Sweep::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      // Numbers of a list, each checked, named in the message.
      auto numbers = [&](const std::string        &name,
                         const bool                positive,
                         std::vector<std::string> *words = nullptr) {
        std::vector<double> values;
        for (const auto &w : Utilities::split_string_list(prm.get(name)))
          {
            if (words != nullptr)
              words->push_back(w);
            if (words != nullptr && w == "half-plane")
              continue;
            const double v = to_number(w);
            require(std::isfinite(v) && (!positive || v > 0),
                    "'Sweep/" + name + "' holds '" + w + "': " +
                      (positive ? "each entry must be a positive number"
                                : "each entry must be a finite number") +
                      (words != nullptr ? " or half-plane" : ""));
            values.push_back(v);
          }
        return values;
      };
      tabor_parameters = numbers("Tabor parameters", true);
      thicknesses.clear();
      numbers("Layer thicknesses", true, &thicknesses);
      approaches = numbers("Approaches", false);
      loads      = numbers("Loads", false);
      // Choices of a list, each checked, named in the message.
      auto choices = [&](const std::string &name, auto &list) {
        using Choice = typename std::decay_t<decltype(list)>::value_type;
        list.clear();
        for (const auto &w : Utilities::split_string_list(prm.get(name)))
          list.push_back(parse_choice<Choice>(w, "Sweep/" + name));
      };
      choices("Controls", controls);
      choices("Solvers", solvers);
      spring_stiffnesses = numbers("Spring stiffnesses", true);
      shapes = Utilities::split_string_list(prm.get("Indenter shapes"));
      prm.leave_subsection();
      require(approaches.empty() || loads.empty(),
              "'Sweep/Approaches' and 'Sweep/Loads' are both given: a "
              "case ends its approach either at a delta_hat or at an F_hat");
    }


    void
    AllParameters::declare(ParameterHandler &prm)
    {
      Output::declare(prm);
      Material::declare(prm);
      Adhesion::declare(prm);
      IndenterProfile::declare(prm);
      Geometry::declare(prm);
      Loading::declare(prm);
      Mesh::declare(prm);
      Sliding::declare(prm);
      Solver::declare(prm);
      BoundaryElement::declare(prm);
      Sweep::declare(prm);
    }

    void
    AllParameters::parse(ParameterHandler &prm)
    {
      output.parse(prm);
      material.parse(prm);
      adhesion.parse(prm);
      indenter.parse(prm);
      geometry.parse(prm);
      loading.parse(prm);
      mesh.parse(prm);
      sliding.parse(prm);
      solver.parse(prm);
      boundary_element.parse(prm);
      sweep.parse(prm);
      solver.verbose = output.verbosity == Verbosity::verbose;
      check_consistency();
      fit_block_to_wake();
      check_mesh_can_hold_case();
      warn_about_accuracy();
    }


    double
    AllParameters::longest_creep_time() const
    {
      return make_solid(*this, Scales(*this)).longest_relaxation_time() /
             material.E0_over_Einf;
    }


    namespace
    {
      // The finest cell p4est can make from the coarse cells is 2^-30 of
      // theirs; the refinement stays well below that.
      constexpr double max_refinement_levels = 24;
      // make_block() tiles the block with squares of its smaller side.
      constexpr double max_aspect_ratio = 1e4;
      // Beyond this distance (in eps) the interaction laws are negligible.
      constexpr double interaction_range = 5;

      // The half-width of the elastic (Hertz) line contact of a cylinder of
      // radius R under F_hat, with plane-strain modulus E_star.
      double
      hertz_half_width(const double                     F_hat,
                       const double                     E_star,
                       const Parameters::AllParameters &p)
      {
        const Scales s(p);
        return std::sqrt(4. * std::max(F_hat, 0.) * s.force * s.R /
                         (M_PI * E_star));
      }
    } // namespace


    // Measured on Fig. 3 (muT 6.08, R_hat 1e4, F_hat 1) at V_hat 1000,
    // against the boundary elements: a block of 2 x 0.4 wake lengths gives
    // a friction 10 % low, 8 x 2 wake lengths 2 % low, 20 x 5 wake lengths
    // (the default) 0.5 % low (doc/model.md, Block and wake).
    void
    AllParameters::fit_block_to_wake()
    {
      // A uniform surface would grow with the block.
      if (sliding.solver == SlidingSolver::transient ||
          geometry.wake_lengths == 0 || sliding.speeds.empty() ||
          mesh.uniform_surface)
        return;
      const double V =
        *std::max_element(sliding.speeds.begin(), sliding.speeds.end());
      const double wake  = V * longest_creep_time();
      const double width = geometry.wake_lengths * wake, depth = width / 4;
      const bool   layer = geometry.substrate == Substrate::layer;
      const bool   force = sliding.control == Control::force;
      const bool   fem   = sliding.solver == SlidingSolver::steady_state;
      const double W0 = geometry.domain_width, H0 = geometry.height();
      // A thin layer keeps to the aspect ratio the mesh can tile.
      if (fem && (force || layer))
        geometry.domain_width =
          std::max(W0, std::min(width, max_aspect_ratio * H0));
      if (force && !layer)
        geometry.domain_height = std::max(H0, depth);

      std::ostringstream note;
      if (geometry.domain_width != W0 || geometry.height() != H0)
        note << "the wake, V tau_c = " << wake << " eps at V_hat " << V
             << ", needs a larger block: " << W0 << " x " << H0
             << " eps widened to " << geometry.domain_width << " x "
             << geometry.height()
             << " ('Geometry/Wake lengths' = " << geometry.wake_lengths << ")"
             << (fem && geometry.domain_width < width
                   ? "; not to the " + num(width) +
                       " eps asked, the mesh tiles at most 1e4 layer "
                       "thicknesses: the friction at the fastest speeds may be "
                       "low"
                   : "");
      else if (fem && (W0 < width || (!layer && H0 < depth)))
        note << "Warning: the wake, V tau_c = " << wake << " eps at V_hat " << V
             << ", does not fit the block of " << W0 << " x " << H0
             << " eps ('Geometry/Wake lengths' = " << geometry.wake_lengths
             << " asks for " << width << " x " << depth
             << "); with this control the block stays as given, and the "
                "friction at the fastest speeds will be low";
      else
        return;
      notes.push_back(note.str());
    }



    // Refuses, before a mesh is built, what the refinement cannot represent
    // and a block the contact does not fit in.
    void
    AllParameters::check_mesh_can_hold_case() const
    {
      const double      W = geometry.domain_width, H = geometry.height();
      const std::string block =
        "the block of " + num(W) + " x " + num(H) + " eps";
      require(std::max(W, H) / std::min(W, H) <= max_aspect_ratio,
              block + " ('Geometry/Domain width', '" +
                (geometry.substrate == Substrate::layer
                   ? "Geometry/Layer thickness"
                   : "Geometry/Domain height") +
                "') has an aspect ratio above 1e4; the mesh tiles it with "
                "squares of its smaller side");
      const double levels = std::log2(std::min(W, H) / mesh.finest_cell);
      require(levels <= max_refinement_levels,
              entry("Mesh", "Finest surface cell", mesh.finest_cell) +
                " is 2^" + num(std::ceil(levels)) +
                " times smaller than the coarse cells of " + block +
                "; at most 2^24 is allowed");
      require(mesh.finest_cell >= 1e-3,
              entry("Mesh", "Finest surface cell", mesh.finest_cell) +
                " is below 1e-3 eps, far finer than the interaction law "
                "needs (0.1 to 1 eps)");

      if (mesh.uniform_surface) // a periodic profile covers the surface
        return;
      // The indenter, pressed to its final depth, must not reach the
      // edges of the block within the range of the interaction.
      const auto   profile = create_indenter(indenter, adhesion.R_over_eps, W);
      double       lowest  = std::numeric_limits<double>::max();
      const double rim =
        std::min(profile->profile(-W / 2), profile->profile(W / 2));
      for (int i = 0; i <= 1000; ++i)
        lowest = std::min(lowest, profile->profile(-W / 2 + W * i / 1000.));
      const bool   force = loading.has_target_load();
      const double stiffest =
        std::max(1., 1. / material.E0_over_Einf); // plane-strain moduli
      double depth = std::max(loading.final_approach, 0.);
      if (force)
        depth =
          geometry.substrate == Substrate::half_plane
            ? std::pow(hertz_half_width(loading.target_load, stiffest, *this),
                       2) /
                (2 * adhesion.R_over_eps)
            : 0.;
      require(
        rim - lowest >= depth + interaction_range,
        block + " is too narrow for the contact: its edges lie " +
          num(rim - lowest) +
          " eps above the lowest point of the indenter, which " +
          (force ? "'Loading/Target load' = " + num(loading.target_load) +
                     " presses about " + num(depth) + " eps deep (Hertz)"
                 : entry("Loading", "Final approach", loading.final_approach) +
                     " presses in") +
          "; widen 'Geometry/Domain width'");
    }


    // Legal but known to be inaccurate: said when the case starts.
    void
    AllParameters::warn_about_accuracy()
    {
      // The cohesive zone of a crack under the law's peak stress: about
      // (pi/8) E* dgamma / sigma_max^2, on the softer modulus.
      const Scales s(*this);
      const double softest = std::min(1., 1. / material.E0_over_Einf);
      const double zone =
        M_PI / 8 * softest * s.dgamma / std::pow(s.sigma_max, 2);
      if (adhesion.law != "repulsive" && adhesion.tabor_parameter > 0 &&
          mesh.finest_cell > zone / 2)
        {
          std::ostringstream note;
          note << "Warning: 'Mesh/Finest surface cell' = " << mesh.finest_cell
               << " eps is coarser than half the adhesive zone (about " << zone
               << " eps); expect the contact edges and the friction "
               << "to be off by several percent";
          notes.push_back(note.str());
        }
      if (sliding.solver == SlidingSolver::transient && sliding.speed > 0)
        notes.push_back(
          "Note: 'Sliding/Solver' = transient slides the indenter until the "
          "contact is steady, typically thousands of eps in steps of the "
          "finest cell: minutes per speed at R_hat 400, 20 minutes to hours "
          "at R_hat 1e4 (doc/benchmark.md). For the steady friction alone, "
          "'Sliding/Solver' = steady-state solves it directly (about a "
          "minute for a curve of 21 speeds at muT 1, 2-eps cells)");
      if (!loading.has_target_load() || mesh.uniform_surface)
        return;
      const double width =
        2 * hertz_half_width(loading.target_load, softest, *this);
      if (width > geometry.domain_width / 4)
        {
          std::ostringstream note;
          note << "Warning: the contact at 'Loading/Target load' = "
               << loading.target_load << " is about " << width
               << " eps wide (Hertz, relaxed modulus), more than a quarter of "
               << "'Geometry/Domain width' = " << geometry.domain_width
               << "; the block's edges will shift the results";
          notes.push_back(note.str());
        }
    }

    void
    AllParameters::check_consistency() const
    {
      // Builds the profile once, so that an unreadable table or a bad
      // expression is reported with the other input errors, before a run.
      create_indenter(indenter, adhesion.R_over_eps, geometry.domain_width);
      require(mesh.finest_cell < geometry.height() / 4,
              entry("Mesh", "Finest surface cell", mesh.finest_cell) +
                " must be well below the substrate height " +
                std::to_string(geometry.height()));
      require(geometry.domain_width >= 2 * geometry.height() ||
                geometry.substrate == Substrate::half_plane,
              entry("Geometry", "Domain width", geometry.domain_width) +
                " must be at least twice the Layer thickness");
      require(!loading.has_target_load() || loading.approach_speed == 0,
              "'Loading/Target load' needs a quasi-static approach "
              "('Loading/Approach speed' = 0): the load is found on the "
              "relaxed loading curve");
      require(sliding.solver == SlidingSolver::transient || !loading.retract ||
                sliding.speed == 0,
              "'Loading/Retract' = true needs 'Sliding/Solver' = transient: "
              "the steady-state solver has no time to retract in");
      require(sliding.speeds.size() == 1 ||
                std::find(sweep.solvers.begin(),
                          sweep.solvers.end(),
                          SlidingSolver::transient) == sweep.solvers.end(),
              "'Sweep/Solvers' with 'transient' needs a single 'Sliding/"
              "Sliding speed' (the transient solver runs each listed speed "
              "as a case of its own; the steady solvers follow the list)");
      if (sliding.solver == SlidingSolver::boundary_element)
        {
          require(sliding.control != Control::spring,
                  "'Sliding/Control' = spring is not available with "
                  "'Sliding/Solver' = boundary-element: use force or "
                  "displacement");
          require(sliding.control == Control::force ||
                    geometry.substrate == Substrate::layer ||
                    sliding.speed == 0,
                  "'Sliding/Solver' = boundary-element on a half-plane "
                  "needs 'Sliding/Control' = force: the periodic "
                  "half-plane has no depth to measure delta from");
          require(loading.approach_speed == 0,
                  "'Sliding/Solver' = boundary-element approaches "
                  "quasi-statically: set 'Loading/Approach speed' = 0");
          const double h = boundary_element.grid_spacing > 0
                             ? boundary_element.grid_spacing
                             : mesh.finest_cell / 2;
          const double L = boundary_element.period > 0 ? boundary_element.period
                                                       : geometry.domain_width;
          require(L / h >= 64 && L / h <= 1e8,
                  entry("Boundary element", "Grid spacing", h) +
                    " and the period " + std::to_string(L) + " eps give " +
                    std::to_string(L / h) +
                    " grid points; between 64 and 1e8 are allowed");
        }
    }
  } // namespace Parameters


  Scales::Scales(const Parameters::AllParameters &p)
    : eps(1.)
    , R(p.adhesion.R_over_eps)
    , E0_star(1.)
    , Einf_star(1. / p.material.E0_over_Einf)
    , dgamma(std::sqrt(std::pow(p.adhesion.tabor_parameter, 3) /
                       p.adhesion.R_over_eps))
    , sigma_max(16. * dgamma / (9. * std::sqrt(3.) * eps))
    , force(std::cbrt(M_PI * dgamma * dgamma * E0_star * R))
    , tau_arm(p.material.time_constant == Parameters::TimeConstant::relaxation
                ? 1.
                : p.material.E0_over_Einf)
    , tau_ref(1.)
  {
  }


  ViscoelasticSolid
  make_solid(const Parameters::AllParameters &p, const Scales &scales)
  {
    const double one_minus_nu2 = 1. - std::pow(p.material.poisson_ratio, 2);
    return ViscoelasticSolid(one_minus_nu2,
                             one_minus_nu2 / p.material.E0_over_Einf,
                             p.material.poisson_ratio,
                             scales.tau_arm,
                             p.material.prony_series);
  }
} // namespace viscoslide
