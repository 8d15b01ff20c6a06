// Helpers shared by the test programs: a checklist that counts failures,
// relative differences, convergence rates and the messages of expected
// errors (scene_tools.h adds runs of scene files).
#ifndef ddcontact_tests_test_tools_h
#define ddcontact_tests_test_tools_h

#include <deal.II/base/convergence_table.h>

#include <cmath>
#include <exception>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace ddcontact
{
  namespace testing
  {
    /** The number of failed checks of this test program. */
    inline int failures = 0;

    /** |a - b| / |b|. */
    inline double
    relative(const double a, const double b)
    {
      return std::abs(a - b) / std::abs(b);
    }

    /** Print one check and count it if it failed. */
    inline void
    check(const bool ok, const std::string &what)
    {
      std::cout << (ok ? "  ok    " : "  FAIL  ") << what << std::endl;
      if (!ok)
        ++failures;
    }

    /** Print one check of an error against its tolerance and count it if
     * the error is larger (or not a number). */
    inline void
    check(const std::string &what, const double error, const double tolerance)
    {
      const bool ok = error <= tolerance;
      std::cout << "  " << std::left << std::setw(60) << what << " error "
                << std::scientific << std::setprecision(2) << error
                << std::defaultfloat << (ok ? "  ok" : "  FAIL") << std::endl;
      if (!ok)
        ++failures;
    }

    /** The end of main(): the verdict line and the exit code. */
    inline int
    report()
    {
      std::cout << (failures == 0 ? "PASSED" : "FAILED") << std::endl;
      return failures == 0 ? 0 : 1;
    }

    /** What error_message() puts before the message of an exception of
     * another type than the expected one. */
    inline const std::string unexpected_error = "(not the expected error) ";

    /** The message of the @p Error that @p f throws, empty if @p f returns
     * normally. Any other exception gives its message behind
     * unexpected_error, so that a check with message_names() fails and
     * the output says why, instead of the program ending there. */
    template <typename Error, typename F>
    std::string
    error_message(const F &f)
    {
      try
      {
        f();
      }
      catch (const Error &e)
      {
        return e.what();
      }
      catch (const std::exception &e)
      {
        return unexpected_error + e.what();
      }
      return "";
    }

    /** Whether @p message, from error_message(), is one of the expected
     * error and contains each of @p fragments. */
    inline bool
    message_names(const std::string              &message,
                  const std::vector<std::string> &fragments)
    {
      if (message.empty() || message.rfind(unexpected_error, 0) == 0)
        return false;
      for (const auto &f : fragments)
        if (message.find(f) == std::string::npos)
          return false;
      return true;
    }

    /** The mean convergence rate over the last two refinements of a
     * sequence of errors on meshes whose h halves each time. */
    inline double
    rate_of_last_two(const std::vector<double> &errors)
    {
      const std::size_t n = errors.size();
      return 0.5 * std::log2(errors[n - 3] / errors[n - 1]);
    }

    /** A ConvergenceTable that gives out the rates it computed. */
    class RateTable : public dealii::ConvergenceTable
    {
    public:
      /** The rates of evaluate_convergence_rates(key, reduction_rate_log2),
       * from the second row on. */
      std::vector<double>
      log2_rates(const std::string &key) const
      {
        const auto &entries = columns.at(key + "...red.rate.log2").entries;
        std::vector<double> rates;
        for (unsigned int i = 1; i < entries.size(); ++i)
          rates.push_back(entries[i].get_numeric_value());
        return rates;
      }
    };

    /** Print @p table with the @p columns in scientific notation and their
     * log2 reduction rates. */
    inline void
    print_with_rates(dealii::ConvergenceTable       &table,
                     const std::vector<std::string> &columns)
    {
      for (const auto &c : columns)
      {
        table.set_scientific(c, true);
        table.set_precision(c, 2);
        table.evaluate_convergence_rates(
          c, dealii::ConvergenceTable::reduction_rate_log2);
      }
      table.write_text(std::cout, dealii::TableHandler::org_mode_table);
    }
  } // namespace testing
} // namespace ddcontact

#endif
