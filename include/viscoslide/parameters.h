// The run-time parameters of viscoslide, grouped as in step-44: one struct
// per subsection, each able to declare its entries (with their documentation)
// and to parse them. Every quantity a user types is dimensionless, in the
// units of ../doc/conventions.md: lengths in eps, times in the chosen time
// constant tau, stresses in E0* (see Scales).
#ifndef viscoslide_parameters_h
#define viscoslide_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <viscoslide/material.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  namespace Parameters
  {
    // The choices of Selection entries, parsed once where the file is read
    // so that a solver never compares strings and an unknown value cannot
    // reach it. to_string() gives the word of the parameter file, which is
    // also what the outputs write.
    enum class Verbosity
    {
      quiet,
      normal,
      verbose
    };
    enum class FieldFormat
    {
      vtu,
      hdf5
    };
    enum class TimeConstant
    {
      relaxation,
      retardation
    };
    enum class Substrate
    {
      half_plane,
      layer
    };
    enum class Control
    {
      displacement,
      force,
      spring
    };
    enum class SlidingSolver
    {
      transient,
      steady_state,
      boundary_element
    };
    enum class LinearSolver
    {
      automatic,
      direct,
      iterative
    };

    // The words of an enum's choices, in the order of its values.
    template <typename Choice>
    const std::vector<std::string> &
    choice_names();

    template <typename Choice>
    std::string
    to_string(const Choice choice)
    {
      return choice_names<Choice>()[static_cast<unsigned int>(choice)];
    }

    // "a|b|c", for Patterns::Selection.
    template <typename Choice>
    std::string
    choice_pattern();

    // The choice a word names; ExcInvalidInput naming `entry` otherwise.
    template <typename Choice>
    Choice
    parse_choice(const std::string &word, const std::string &entry);

    struct Output
    {
      std::string  directory;
      Verbosity    verbosity;
      unsigned int fields_every;
      unsigned int profile_every;
      unsigned int checkpoint_every; // sliding steps; 0: none
      bool         write_fields;
      FieldFormat  field_format;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Material
    {
      double       E0_over_Einf;
      double       poisson_ratio;
      TimeConstant time_constant;
      // Arms of the generalised Maxwell solid; empty: one arm, the
      // standard linear solid.
      std::vector<PronyTerm> prony_series;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Adhesion
    {
      std::string  law; // "lennard-jones" or "repulsive"
      double       tabor_parameter;
      double       R_over_eps;
      double       contact_gap;
      unsigned int face_quadrature_points;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    // The rigid profile h(x) (lengths in eps); the entries are documented
    // in IndenterProfile::declare, the shapes in indenter.h.
    struct IndenterProfile
    {
      std::string shape;      // parabola|circle|flat punch|power law|sinusoid|
                              // expression|table
      double      half_width; // flat punch
      double      corner_radius; // flat punch
      double      exponent;      // power law
      double      amplitude;     // sinusoid
      double      wavelength;    // sinusoid
      std::string expression;    // expression: h(x) in muParser syntax
      std::string profile_file;  // table: CSV x_over_eps,h_over_eps

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Geometry
    {
      Substrate substrate;
      double    layer_thickness;
      double    domain_width;
      double    domain_height;
      double    wake_lengths;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      // The height of the block actually meshed.
      double
      height() const
      {
        return substrate == Substrate::layer ? layer_thickness : domain_height;
      }
    };

    struct Loading
    {
      double       initial_approach;
      double       final_approach;
      double       increment;
      double       minimum_increment;
      double       approach_speed;
      double       hold_time;
      unsigned int hold_steps;
      bool         retract;
      double       retract_to;
      // F_hat to reach at the end of the approach; NaN: none, the approach
      // ends at final_approach.
      double target_load;

      bool
      has_target_load() const
      {
        return !std::isnan(target_load);
      }

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Mesh
    {
      double       finest_cell;
      double       grading;
      double       edge_gap_low;
      double       edge_gap_high;
      double       edge_margin; // in eps
      unsigned int max_adaptation_cycles;
      bool         uniform_surface;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Sliding
    {
      std::vector<double> speeds; // V_hat, in the order of continuation
      double              speed;  // the last of them; 0: no sliding phase
      Control             control;
      double              spring_stiffness; // k_hat, Control = spring
      double              increment;        // in finest cells
      double              max_distance;
      double              steady_tolerance;
      double              steady_window;
      SlidingSolver       solver;
      double              continuation_factor;
      int                 viscous_strain_degree;
      // F_hat (force control) or delta_hat (displacement control) values
      // followed at the last speed by the steady-state solver.
      std::vector<double> load_path;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    // The grid of the boundary-element solver (boundary_element/solver.h).
    struct BoundaryElement
    {
      double grid_spacing; // eps; 0: half the Finest surface cell
      double period;       // eps; 0: automatic
      double wake_periods; // the automatic period, in V tau_c
      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
    struct Solver
    {
      LinearSolver linear_solver;
      unsigned int direct_solver_limit;
      double       newton_tolerance;
      unsigned int max_newton_iterations;
      bool         line_search;
      unsigned int max_relaxation_steps;
      bool         verbose;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    // The lists whose product is a sweep. An empty list leaves the entry of
    // its own section alone; see doc/sweeps.md.
    struct Sweep
    {
      std::vector<double>        tabor_parameters;
      std::vector<std::string>   thicknesses; // numbers or "half-plane"
      std::vector<double>        approaches;
      std::vector<double>        loads;
      std::vector<Control>       controls;
      std::vector<SlidingSolver> solvers;
      std::vector<double>        spring_stiffnesses;
      std::vector<std::string>   shapes;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    // All parameters of one run. The constructor declares; parse() reads a
    // file, checks ranges and cross-entry consistency, and throws
    // ExcInvalidInput with the entry name and value on the first violation.
    struct AllParameters
    {
      Output          output;
      Material        material;
      Adhesion        adhesion;
      IndenterProfile indenter;
      Geometry        geometry;
      Loading         loading;
      Mesh            mesh;
      Sliding         sliding;
      Solver          solver;
      BoundaryElement boundary_element;
      Sweep           sweep;

      // What the program changed in the case or doubts about it, said
      // once when the case starts (for example the block widened to hold
      // the wake).
      std::vector<std::string> notes;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      // The creep (retardation) time of the slowest arm, in the time unit
      // of V_hat: V_hat times it is the wake length behind the contact in
      // eps.
      double
      longest_creep_time() const;

    private:
      void
      check_consistency() const;
      void
      fit_block_to_wake();
      void
      check_mesh_can_hold_case() const;
      void
      warn_about_accuracy();
    };

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


  // Internal units: eps = 1, E0* = E0/(1-nu^2) = 1 and the user's time
  // constant tau_ref = 1. Everything that turns internal numbers into the
  // paper's dimensionless groups lives here, so that no output invents its
  // own normalisation.
  struct Scales
  {
    explicit Scales(const Parameters::AllParameters &p);

    double eps;       // interaction range (= 1)
    double R;         // indenter radius, R_hat eps
    double E0_star;   // plane-strain relaxed modulus (= 1)
    double Einf_star; // plane-strain instantaneous modulus
    double dgamma;    // work of adhesion, sqrt(muT^3/R_hat) E0* eps
    double sigma_max; // Lennard-Jones peak traction
    double force;     // (pi dgamma^2 E0* R)^(1/3), the F_hat unit
    double tau_arm;   // relaxation time of the Maxwell arm
    double tau_ref;   // the time unit of V_hat and time_over_tau (= 1)
  };

  // The solid of the parameters in internal units: E0 = 1 - nu^2, so that
  // E0* = 1, and the arms' times in tau_ref.
  ViscoelasticSolid
  make_solid(const Parameters::AllParameters &p, const Scales &scales);
} // namespace viscoslide

#endif
