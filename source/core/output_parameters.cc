/* The entries of the output (.prm subsection Output): declaration,
   parsing and checks. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <core/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Contact
{
  namespace
  {
    // Each report prints the state of Gamma_3 (and with VTU output writes
    // a file): more than this many cannot be meant.
    constexpr unsigned int max_report_times = 10000;

    // Numbers separated by ',', read in one pass, at most
    // max_report_times of them.
    std::vector<double> parse_report_times(const std::string &text)
    {
      std::vector<double> times;
      if (Utilities::trim(text).empty())
        return times;
      for (std::size_t begin = 0; begin <= text.size();)
        {
          const std::size_t end = std::min(text.find(',', begin), text.size());
          AssertThrow(times.size() < max_report_times,
                      ExcMessage(
                        "Entry 'Output/Report times' has more than " +
                        std::to_string(max_report_times) +
                        " times; allowed are at most that many (each "
                        "prints the state of Gamma_3, and with VTU output "
                        "writes a file)."));
          const std::string number =
            Utilities::trim(text.substr(begin, end - begin));
          char        *stop = nullptr;
          const double t    = std::strtod(number.c_str(), &stop);
          AssertThrow(!number.empty() && *stop == '\0' && std::isfinite(t),
                      ExcMessage("Entry 'Output/Report times': cannot read '" +
                                 number +
                                 "' as a time; allowed are finite numbers "
                                 "separated by ','."));
          times.push_back(t);
          begin = end + 1;
        }
      return times;
    }
  } // namespace


  // @sect3{Output}

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    // After each entry, those of the postprocessors that follow it.
    const auto declare_entry = [&prm](const std::string           &name,
                                      const std::string           &value,
                                      const Patterns::PatternBase &pattern,
                                      const std::string           &help) {
      prm.declare_entry(name, value, pattern, help);
      Parts::declare_entries_after(prm, "Output", name);
    };
    prm.enter_subsection("Output");
    {
      declare_entry("Output directory",
                    "results-barboteu2015",
                    Patterns::Anything(),
                    "Directory for VTU/PVD, time_series.csv and "
                    "parameters.prm, relative to where the program runs. "
                    "A run that is not resumed replaces the results of "
                    "an earlier run there (its VTU/PVD, time series, "
                    "Gamma_3 history, parameters, checkpoints, error "
                    "estimate with its coarse-* runs and a study's table "
                    "with its level-N); one run at a time "
                    "may use it (the lock file .lock names the run).");
      // Read by parse_report_times(): deal.II's Patterns::List splits its
      // text in a time quadratic in its length.
      declare_entry("Report times",
                    "0.3, 1.1",
                    Patterns::Anything(),
                    "Times [s] > 0, separated by ',', at which the stick/slip "
                    "state of Gamma_3 is printed (at the nearest step), at "
                    "most " +
                      std::to_string(max_report_times) + ".");
      declare_entry("Probe points",
                    "",
                    Patterns::Anything(),
                    "Points 'x, y[, z]' separated by ';' whose "
                    "displacement is written to time_series.csv "
                    "(columns probe<i>_u_x, ...). On a shell a point "
                    "between its radii that the cells miss by the "
                    "geometry error of their curved boundary is taken "
                    "at the nearest point of the cell around it.");
      declare_entry("Print timings",
                    "true",
                    Patterns::Bool(),
                    "Print the wall time summary at the end (switch off "
                    "for tests).");
      declare_entry("Checkpoint interval",
                    "0",
                    Patterns::Integer(0),
                    "Write a checkpoint (output directory/checkpoint) "
                    "every this many steps, and at the end; 0: by steps "
                    "never.");
      declare_entry("Checkpoint minutes",
                    "0",
                    Patterns::Double(0),
                    "Write a checkpoint when this many minutes of wall "
                    "time have passed since the last one, and at the "
                    "end; 0: by time never.");
      declare_entry(
        "Resume",
        "false",
        Patterns::Bool(),
        "Continue the run from the checkpoint in the output directory "
        "(the command line option --resume sets this). The scene must be the "
        "same; a later 'Time/End time' with the same time step extends a "
        "finished run. time_series.csv and solution.pvd are cut back to the "
        "checkpoint's step.");
    }
    prm.leave_subsection();
  }

  void OutputParameters::parse_parameters(ParameterHandler  &prm,
                                          const unsigned int dim)
  {
    prm.enter_subsection("Output");
    {
      directory    = Utilities::trim(prm.get("Output directory"));
      report_times = parse_report_times(prm.get("Report times"));
      probe_points =
        parse_points(prm.get("Probe points"), dim, "Output/Probe points");
      print_timings       = prm.get_bool("Print timings");
      checkpoint_interval = prm.get_integer("Checkpoint interval");
      checkpoint_minutes  = prm.get_double("Checkpoint minutes");
      resume              = prm.get_bool("Resume");
    }
    prm.leave_subsection();

    AssertThrow(!directory.empty(),
                ExcMessage("The entry 'Output/Output directory' is empty: "
                           "allowed is a directory name."));
    // The used parameters are written to <directory>/parameters.prm, where
    // '#' would start a comment and a newline end the entry.
    AssertThrow(directory.find_first_of("#\n\\") == std::string::npos,
                ExcMessage("The entry 'Output/Output directory' = '" +
                           directory +
                           "' contains '#', '\\' or a line break, which "
                           "parameters.prm cannot hold; allowed is a "
                           "directory name without them."));
    for (const double t : report_times)
      check_entry(t > 0,
                  "Output/Report times",
                  t,
                  "times t > 0 (t = 0 is the initial state; times after "
                  "'Time/End time' are reported at the last step)");
  }
} // namespace Contact
