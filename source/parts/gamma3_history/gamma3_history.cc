/* gamma3_history.csv ('Output/Gamma3 history'): the state of every node
   of Gamma_3 at every step. */

#include <core/csv_file.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>

#include <iomanip>

namespace Contact
{
  namespace
  {
    const ResultFiles history_files("gamma3_history\\.csv(\\.tmp)?");

    // @sect4{The entry 'Gamma3 history'}

    const std::string history_entry = "Gamma3 history";

    const PartEntries own_entries{
      "Output",
      "Time series",
      history_entry,
      [](ParameterHandler &prm) {
        prm.declare_entry(
          history_entry,
          "true",
          Patterns::Bool(),
          "Write gamma3_history.csv: for every time step one row per node "
          "of Gamma_3 (its position, stick or slip, slip rate, friction "
          "traction and bound), the data of a space-time diagram of the "
          "slip front (doc/plot_run.py).");
      },
      [](ParameterHandler &prm, const Parameters &) -> std::any {
        return prm.get_bool(history_entry);
      }};
  } // namespace


  template <int dim>
  class Gamma3History : public Postprocessor<dim>
  {
  public:
    void start(const bool resumed) override;

    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end == StepEnd::whole_step)
        write_rows();
    }

  private:
    void write_rows();

    CsvFile file;
  };


  // @sect4{Gamma3History::start}

  // The file is written by the first process (every process has all nodes
  // of Gamma_3).
  template <int dim>
  void Gamma3History<dim>::start(const bool resumed)
  {
    if (!this->parameters().template part<bool>("gamma3 history") ||
        Utilities::MPI::this_mpi_process(this->mpi_communicator()) != 0)
      return;
    file.open(this->parameters().output.directory + "/gamma3_history.csv",
              std::string("step,time,x,y") + (dim == 3 ? ",z" : "") +
                ",state,slip_rate,friction_traction_t1" +
                (dim == 3 ? ",friction_traction_t2" : "") + ",friction_bound",
              resumed,
              this->state().step_number);
    if (!resumed)
      write_rows();
  }


  // @sect4{Gamma3History::write_rows}

  // The state of every node of Gamma_3 at t_n (every process has all of
  // them; the first one writes): state 1 stick, 2 slip; the friction
  // traction -eta_p / m_p in the node's tangent basis (t1 is the direction
  // of +x on the paper's Gamma_3), and the bound mu(|w_tau|) S.
  template <int dim>
  void Gamma3History<dim>::write_rows()
  {
    if (!file.is_open())
      return;
    const std::vector<ContactNode<dim>> &contact_nodes =
      this->friction_solver().boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      this->friction_solver().state();
    std::ofstream &gamma3_history = file.stream();
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        const ContactNode<dim> &node = contact_nodes[p];
        const double rate = node.tangential_vector(slip_velocity, p).norm();
        gamma3_history << this->state().step_number << ','
                       << std::setprecision(12) << this->state().time;
        for (unsigned int d = 0; d < dim; ++d)
          gamma3_history << ',' << node.location[d];
        gamma3_history << ',' << (node_state[p] == NodeState::stick ? 1 : 2)
                       << ',' << rate;
        for (unsigned int i = 0; i < dim - 1; ++i)
          gamma3_history << ','
                         << (node.weight > 0 ?
                               -friction_force[p * (dim - 1) + i] /
                                 node.weight :
                               0.);
        gamma3_history << ',' << this->friction_law().bound(rate) << '\n';
      }
    file.check();
  }



  namespace
  {
    const PostprocessorRegistration<Gamma3History>
      registration("gamma3 history", 60, own_entries);
  }
} // namespace Contact
