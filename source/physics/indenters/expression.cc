// SPDX-License-Identifier: LGPL-2.1-or-later
// h(x) typed as a muParser expression in x (eps) with the constant R
// (= R_hat); the slope by central differences (FunctionParser is an
// AutoDerivativeFunction).
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <viscoslide/physics/indenter.h>

#include <cmath>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    class Expression : public Indenter
    {
    public:
      Expression(const std::string &expression, const double R)
        // a difference step of 1e-6 eps: round-off stays below 1e-8 for
        // profiles of up to 1e2 R_hat
        : function(1, 0., 1e-6)
      {
        try
          {
            function.initialize("x", expression, {{"R", R}, {"pi", M_PI}});
            function.value(Point<1>(0.)); // muParser parses on first use
          }
        catch (ExceptionBase &e)
          {
            std::ostringstream message;
            e.print_info(message);
            throw Parameters::ExcInvalidInput(
              "'Indenter/Expression' = " + expression +
              " is not a function of x: " + Utilities::trim(message.str()));
          }
      }

      double
      profile(const double xi) const override
      {
        return function.value(Point<1>(xi));
      }

      double
      slope(const double xi) const override
      {
        return function.gradient(Point<1>(xi))[0];
      }

    private:
      FunctionParser<1> function;
    };

    void
    declare(ParameterHandler &prm)
    {
      prm.declare_entry("Expression",
                        "x^2/(2*R)",
                        Patterns::Anything(),
                        "Expression: h as a muParser function of x (both in "
                        "eps), with the constants R (= R_hat) and pi, e.g. "
                        "'x^2/(2*R) + 1e-7*x^4'. Its slope is taken by "
                        "central differences of 1e-6 eps.");
    }

    IndenterMaker
    parse(ParameterHandler &prm)
    {
      const std::string expression = prm.get("Expression");
      return [expression](const double R) {
        return std::make_unique<Expression>(expression, R);
      };
    }
  } // namespace

  VISCOSLIDE_REGISTER(
    IndenterShape,
    {"expression", "the muParser Expression.", declare, parse})
} // namespace viscoslide
