/* The VTU/PVD output ('Output/VTU interval', 'Output/Report times'):
   the fields of a step as solution_NNNNN.pvtu with one piece per process,
   listed in solution.pvd. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>

#include <deal.II/numerics/data_out.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <core/slip_zone.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <set>

namespace Contact
{
  namespace
  {
    const ResultFiles vtu_files(
      "solution_[0-9]{5}\\.([0-9]+\\.vtu|pvtu)|solution\\.pvd(\\.tmp)?");

    // @sect4{The entry 'VTU interval'}

    const std::string interval_entry = "VTU interval";

    const PartEntries own_entries{
      "Output",
      "Output directory",
      interval_entry,
      [](ParameterHandler &prm) {
        prm.declare_entry(interval_entry,
                          "8",
                          Patterns::Integer(0),
                          "Write a VTU file every this many steps, at the "
                          "initial and final time and at the step nearest "
                          "to each of the Report times; 0 writes none.");
      },
      // A VTU file per step of a long run fills a disk without a word.
      [](ParameterHandler &prm, const Parameters &parameters) -> std::any {
        const unsigned int interval      = prm.get_integer(interval_entry);
        const unsigned int n_steps       = parameters.time.n_steps();
        const unsigned int max_vtu_files = 10000;
        check_entry(interval == 0 || n_steps / interval <= max_vtu_files,
                    "Output/" + interval_entry,
                    interval,
                    "0 (none) or at least N / " +
                      std::to_string(max_vtu_files) + " = " +
                      std::to_string(n_steps / max_vtu_files + 1) +
                      " for the N = " + std::to_string(n_steps) +
                      " steps of this run (at most " +
                      std::to_string(max_vtu_files) + " VTU files)");
        return interval;
      }};

    // The value at each hanging node that the continuity of a field asks
    // for, from the nodes it follows: the fields of Gamma_3 are set at the
    // friction nodes only, and a hanging node of Gamma_3 is none.
    // A category (the contact status) takes the largest of the nodes it
    // follows instead: a node between a sticking and a slipping one slips.
    // Only hanging nodes on Gamma_3 (`on_gamma3`) carry these fields: one
    // inside the body that follows a node of Gamma_3 keeps its 0.
    template <typename Vector>
    void set_hanging_values(const AffineConstraints<double> &hanging,
                            const IndexSet                  &lines,
                            const IndexSet                  &on_gamma3,
                            Vector                          &field,
                            const bool                       category = false)
    {
      for (const auto &line : hanging.get_lines())
        if (lines.is_element(line.index) && on_gamma3.is_element(line.index))
          {
            double value = 0;
            for (const auto &[dof, c] : line.entries)
              value = category ? std::max<double>(value, field(dof)) :
                                 value + c * field(dof);
            field(line.index) = value;
          }
    }


    // DataOut whose patches the next output on the same mesh fills with its
    // own values (VtuOutput::refresh_patches()) instead of building them
    // again; clear_input_data_references() keeps the field names and
    // releases the vectors they came from.
    template <int dim>
    class ReusablePatches : public DataOut<dim>
    {
    public:
      std::vector<DataOutBase::Patch<dim>> &built_patches()
      {
        return this->patches;
      }

      // Where the values of the patches come from, found on the first
      // refill and read by the later ones (a gather, without the DoF
      // handlers): for each point of each patch, the local indices of the
      // dim components of the vector fields at its vertex in their ghosted
      // vectors and the index of the scalar fields' DoF there; for each
      // patch, the index of its cell in the cell fields.
      std::vector<types::global_dof_index> point_dofs;
      std::vector<unsigned int>            patch_cells;
    };
  } // namespace


  // @sect4{VtuOutput}

  // One VTU output: copies of the fields at t_n, and the thread that turns
  // them into a file. The patches and deal.II's compression and encoding
  // of the file take most of an output's time (bench/output.md measures
  // what the output adds to a run and where its time goes); they run in a
  // background thread while the time loop goes on, and finish_vtu() waits
  // for them before the next output, a checkpoint, a change of the mesh or
  // the end of the run. What does not change with the step is found once
  // per mesh: DataOut builds the patches of the first output on a mesh and
  // the later ones refill them (refresh_patches()), and the cell averages
  // of the stress use the averages of the shape functions' gradients
  // (cell_average_stress()). The thread reads the mesh, the DoFHandlers
  // and the mapping, which the steps do not change, and makes no MPI
  // calls: DataOut's ghosted copies of the fields (MPI calls) are made
  // before it starts.
  template <int dim>
  class VtuOutput : public Postprocessor<dim>
  {
  public:
    // A run that ends with an error completes the output of the last
    // written step; on several processes the others may not get here, and
    // its pieces stay in .partial/ (the PVD does not list them).
    ~VtuOutput() override;

    // The thread reads the mesh that is about to change.
    void mesh_event(const MeshEvent event) override
    {
      if (event == MeshEvent::initial)
        report_times = ReportTimes(this->parameters().output.report_times);
      else if (event == MeshEvent::before_change)
        {
          finish_vtu();
          mesh_patches.reset();
          mean_gradients.clear();
        }
    }

    void start(const bool resumed) override;
    void after_step(const StepStatistics &, const StepEnd end) override;

    // The checkpoint lists the records written so far. The report times of
    // a resumed run are this run's after the checkpoint
    // (ReportTimes::drop_met()), not the checkpointed run's.
    void checkpoint(CheckpointArchive &archive) override
    {
      if (!archive.is_loading())
        finish_vtu();
      archive &pvd_records &report_times;
      if (!archive.is_loading())
        return;
      report_times = ReportTimes(this->parameters().output.report_times);
      report_times.drop_met(this->state().step_number, this->time_step());
    }

    void finish(RunSummary &) override
    {
      finish_vtu();
    }

  private:
    struct Pending
    {
      double                      time;
      unsigned int                step;
      FastVector                  displacement, velocity, friction_traction;
      Vector<double>              status, slip_rate, friction_bound;
      std::vector<Vector<double>> stress;
      Vector<double>              von_mises;
      // The patches of the previous output on this mesh, if they can be
      // refilled (refresh_patches()); else fields for a new DataOut.
      std::shared_ptr<ReusablePatches<dim>> data_out;
      bool                                  refresh = false;
      std::future<void>                     written;
    };

    std::string vtu_piece_name(const unsigned int step,
                               const unsigned int process) const;
    void        write_vtu();
    void        cell_average_stress(Pending &output);
    void        find_mean_gradients();
    void        add_hanging_values(Pending &output) const;
    void        add_vtu_fields(Pending &output) const;
    void        refresh_patches(Pending &output) const;
    void        find_patch_sources(Pending &output) const;
    void        write_vtu_piece(Pending &output, const std::string &file) const;
    void        finish_vtu();
    void        write_pvd() const;
    void        drop_missing_records();

    std::vector<std::pair<double, std::string>> pvd_records;
    ReportTimes                                 report_times;
    // The patches of the last output on the current mesh (null before the
    // first one, after a change of the mesh and for elements of degree
    // above 1, whose patches are not filled from their vertices).
    std::shared_ptr<ReusablePatches<dim>> mesh_patches;
    // For each locally owned cell of the current mesh, in order, the
    // averages over it of the gradients of the shape functions of the
    // scalar element (empty before the first output on a mesh; see
    // cell_average_stress()).
    std::vector<Tensor<1, dim>> mean_gradients;
    // The output being written in the background, last so that it is
    // destroyed first.
    std::shared_ptr<Pending> pending_vtu;
  };


  template <int dim>
  VtuOutput<dim>::~VtuOutput()
  {
    if (pending_vtu &&
        Utilities::MPI::n_mpi_processes(this->mpi_communicator()) == 1)
      try
        {
          finish_vtu();
        }
      catch (...)
        {
          // An output error while another error ends the run: the first
          // one is reported.
        }
  }


  // @sect4{VtuOutput::start}

  // A fresh run writes its initial state; a resumed one the PVD of the
  // records stored with the checkpoint (the killed run may have listed
  // steps after it, which are computed again).
  template <int dim>
  void VtuOutput<dim>::start(const bool resumed)
  {
    if (resumed)
      {
        drop_missing_records();
        write_pvd();
      }
    else if (this->parameters().template part<unsigned int>("VTU output") > 0)
      write_vtu();
  }


  // @sect4{VtuOutput::after_step}

  // Every 'VTU interval' steps, at the last step and at the step nearest
  // to each report time.
  template <int dim>
  void VtuOutput<dim>::after_step(const StepStatistics &, const StepEnd end)
  {
    if (end != StepEnd::whole_step)
      return;
    const unsigned int interval =
      this->parameters().template part<unsigned int>("VTU output");
    const unsigned int step = this->state().step_number;
    const bool         last = (step == this->n_time_steps());
    const bool         reported =
      !report_times.take_due(this->state().time, this->time_step(), last)
         .empty();
    if (interval > 0 && (step % interval == 0 || last || reported))
      write_vtu();
  }



  // @sect4{VtuOutput::vtu_piece_name}

  // deal.II's names for the pieces of a parallel VTU output and their
  // record: solution_00012.0.vtu, ..., solution_00012.pvtu.
  template <int dim>
  std::string VtuOutput<dim>::vtu_piece_name(const unsigned int step,
                                             const unsigned int process) const
  {
    return "solution_" + Utilities::int_to_string(step, 5) + "." +
           Utilities::int_to_string(process) + ".vtu";
  }


  // @sect4{VtuOutput::write_vtu}

  // Displacement and velocity as vectors; on Gamma_3 the status (0: off
  // Gamma_3, 1: stick, 2: slip), the slip rate |w_tau|, the friction
  // traction -eta_p/m_p t_p and the bound mu(|w_tau|) S, as nodal fields;
  // the stress of (3.1) as cell averages (cell_stress_*, cell_von_mises,
  // see cell_average_stress()). Here the fields are copied and handed to
  // DataOut; the patches and the file are made in the background
  // (VtuOutput).
  template <int dim>
  void VtuOutput<dim>::write_vtu()
  {
    const DiscreteSpace<dim> &space = this->space();
    finish_vtu();
    TimerOutput::Scope t(this->computing_timer(), "Output");

    auto output          = std::make_shared<Pending>();
    output->time         = this->state().time;
    output->step         = this->state().step_number;
    output->displacement = space.fast_ghosted(this->state().displacement);
    output->velocity     = space.fast_ghosted(this->state().velocity);

    const unsigned int n_scalar_dofs = space.scalar_dof_handler.n_dofs();
    output->status.reinit(n_scalar_dofs);
    output->slip_rate.reinit(n_scalar_dofs);
    output->friction_bound.reinit(n_scalar_dofs);
    output->friction_traction.reinit(space.locally_owned_dofs,
                                     space.locally_relevant_dofs,
                                     this->mpi_communicator());
    const std::vector<ContactNode<dim>> &contact_nodes =
      this->friction_solver().boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      this->friction_solver().state();
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        const ContactNode<dim> &node = contact_nodes[p];
        const double rate = node.tangential_vector(slip_velocity, p).norm();
        output->status[node.scalar_dof] =
          (node_state[p] == NodeState::stick ? 1 : 2);
        output->slip_rate[node.scalar_dof] = rate;
        output->friction_bound[node.scalar_dof] =
          this->friction_law().bound(rate);
        if (node.weight > 0 && node.locally_owned)
          for (unsigned int d = 0; d < dim; ++d)
            output->friction_traction[node.dofs[d]] =
              -node.tangential_vector(friction_force, p)[d] / node.weight;
      }
    output->friction_traction.update_ghost_values();
    add_hanging_values(*output);
    cell_average_stress(*output);
    output->refresh = (mesh_patches != nullptr);
    if (output->refresh)
      output->data_out = std::move(mesh_patches);
    else
      add_vtu_fields(*output);

    const std::string piece = this->parameters().output.directory +
                              "/.partial/" +
                              vtu_piece_name(this->state().step_number,
                                             Utilities::MPI::this_mpi_process(
                                               this->mpi_communicator()));
    Pending &fields = *output;
    output->written = std::async(std::launch::async, [this, &fields, piece]() {
      write_vtu_piece(fields, piece);
    });
    pending_vtu     = std::move(output);
  }


  // @sect4{VtuOutput::add_hanging_values}

  // Hanging nodes of Gamma_3 (a refined part of it) carry no friction
  // unknown: their fields follow from the nodes they hang on.
  template <int dim>
  void VtuOutput<dim>::add_hanging_values(Pending &output) const
  {
    const DiscreteSpace<dim> &space = this->space();
    if (!space.dof_handler.get_triangulation().has_hanging_nodes())
      return;
    IndexSet scalar_relevant;
    DoFTools::extract_locally_relevant_dofs(space.scalar_dof_handler,
                                            scalar_relevant);
    AffineConstraints<double> scalar_hanging(scalar_relevant);
    DoFTools::make_hanging_node_constraints(space.scalar_dof_handler,
                                            scalar_hanging);
    scalar_hanging.close();
    const std::vector<types::boundary_id> &ids =
      this->parameters().boundary.contact_ids;
    const std::set<types::boundary_id> contact_ids(ids.begin(), ids.end());
    const IndexSet                     scalar_on_gamma3 =
      DoFTools::extract_boundary_dofs(space.scalar_dof_handler,
                                      ComponentMask(),
                                      contact_ids);
    set_hanging_values(
      scalar_hanging, scalar_relevant, scalar_on_gamma3, output.status, true);
    for (Vector<double> *field : {&output.slip_rate, &output.friction_bound})
      set_hanging_values(scalar_hanging,
                         scalar_relevant,
                         scalar_on_gamma3,
                         *field);

    const AffineConstraints<double> &hanging = space.hanging_node_constraints;
    set_hanging_values(hanging,
                       space.locally_owned_dofs,
                       DoFTools::extract_boundary_dofs(space.dof_handler,
                                                       ComponentMask(),
                                                       contact_ids),
                       output.friction_traction);
    output.friction_traction.update_ghost_values();
  }


  // @sect4{VtuOutput::cell_average_stress}

  // The stress sigma = A eps(w) + B eps(u) of (3.1) averaged over each
  // cell, and the von Mises value of that average (in 2D plane strain
  // sigma_zz = lambda tr eps(u) + mu_1 tr eps(w) enters it). sigma is
  // linear in the gradients of u and w, so its average is A and B applied
  // to the symmetric parts of their averages: the average of grad u is the
  // sum over the cell's DoFs of u_i e_c (x) the average of grad psi_j, for
  // the component c of the DoF and the shape function psi_j of the scalar
  // element it is a copy of. find_mean_gradients() computes those averages
  // once per mesh: an output reads each cell's DoF values and no shape
  // function.
  template <int dim>
  void VtuOutput<dim>::cell_average_stress(Pending &output)
  {
    const DiscreteSpace<dim> &space    = this->space();
    const auto               &material = this->parameters().material;
    const double              two_G    = material.two_G();
    const double              lambda   = material.lambda(dim);
    const bool                plane_strain =
      (dim == 2 &&
       material.plane_model == MaterialParameters::PlaneModel::plane_strain);
    if (mean_gradients.empty())
      find_mean_gradients();

    const unsigned int n_cells = space.triangulation->n_active_cells();
    output.stress.assign(dim * (dim + 1) / 2, Vector<double>(n_cells));
    output.von_mises.reinit(n_cells);
    std::vector<double> u_cell(space.fe.n_dofs_per_cell()),
      w_cell(space.fe.n_dofs_per_cell());
    auto mean_gradient = mean_gradients.cbegin();
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(output.displacement,
                               u_cell.begin(),
                               u_cell.end());
          cell->get_dof_values(output.velocity, w_cell.begin(), w_cell.end());
          Tensor<2, dim> grad_u, grad_w;
          for (unsigned int i = 0; i < u_cell.size(); ++i)
            {
              const auto [c, j] = space.fe.system_to_component_index(i);
              grad_u[c] += u_cell[i] * mean_gradient[j];
              grad_w[c] += w_cell[i] * mean_gradient[j];
            }
          mean_gradient += space.scalar_fe->n_dofs_per_cell();
          const SymmetricTensor<2, dim> eps_u = symmetrize(grad_u),
                                        eps_w = symmetrize(grad_w);
          const SymmetricTensor<2, dim> sigma =
            material.viscosity_mu1 * trace(eps_w) *
              unit_symmetric_tensor<dim>() +
            material.viscosity_mu2 * eps_w +
            lambda * trace(eps_u) * unit_symmetric_tensor<dim>() +
            two_G * eps_u;
          const double sigma_zz =
            (plane_strain ?
               lambda * trace(eps_u) + material.viscosity_mu1 * trace(eps_w) :
               0.);
          const unsigned int c         = cell->active_cell_index();
          unsigned int       component = 0;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              output.stress[component++][c] = sigma[i][j];
          const double                  mean = (trace(sigma) + sigma_zz) / 3.;
          const SymmetricTensor<2, dim> deviator =
            sigma - mean * unit_symmetric_tensor<dim>();
          const double out_of_plane = (dim == 2 ? sigma_zz - mean : 0.);
          output.von_mises[c]       = std::sqrt(
            1.5 * (deviator * deviator + out_of_plane * out_of_plane));
        }
  }


  // The averages over each locally owned cell of the gradients of the
  // scalar element's shape functions, by the quadrature of the assembly.
  template <int dim>
  void VtuOutput<dim>::find_mean_gradients()
  {
    const DiscreteSpace<dim> &space = this->space();
    FEValues<dim>             fe_values(*space.mapping,
                            *space.scalar_fe,
                            space.quadrature,
                            update_gradients | update_JxW_values);
    for (const auto &cell : space.triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          double volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            volume += fe_values.JxW(q);
          for (const unsigned int j : fe_values.dof_indices())
            {
              Tensor<1, dim> mean;
              for (const unsigned int q : fe_values.quadrature_point_indices())
                mean += fe_values.shape_grad(j, q) * fe_values.JxW(q);
              mean_gradients.push_back(mean / volume);
            }
        }
  }


  // @sect4{VtuOutput::add_vtu_fields}

  // DataOut makes ghosted copies of the nodal fields (an MPI call, so here,
  // before the output thread starts).
  template <int dim>
  void VtuOutput<dim>::add_vtu_fields(Pending &output) const
  {
    const DiscreteSpace<dim> &space = this->space();
    output.data_out                 = std::make_shared<ReusablePatches<dim>>();
    DataOut<dim> &data_out          = *output.data_out;
    data_out.attach_dof_handler(space.dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim,
                   DataComponentInterpretation::component_is_part_of_vector);
    const std::vector<std::pair<const FastVector *, std::string>> fields = {
      {&output.displacement, "displacement"},
      {&output.velocity, "velocity"},
      {&output.friction_traction, "friction_traction"}};
    for (const auto &[vector, name] : fields)
      data_out.add_data_vector(*vector,
                               std::vector<std::string>(dim, name),
                               DataOut<dim>::type_dof_data,
                               vector_field);
    data_out.add_data_vector(space.scalar_dof_handler,
                             output.status,
                             "contact_status");
    data_out.add_data_vector(space.scalar_dof_handler,
                             output.slip_rate,
                             "slip_rate");
    data_out.add_data_vector(space.scalar_dof_handler,
                             output.friction_bound,
                             "friction_bound");
    const char  *axes      = "xyz";
    unsigned int component = 0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        data_out.add_data_vector(output.stress[component++],
                                 std::string("cell_stress_") + axes[i] +
                                   axes[j],
                                 DataOut<dim>::type_cell_data);
    data_out.add_data_vector(output.von_mises,
                             "cell_von_mises",
                             DataOut<dim>::type_cell_data);
  }


  // @sect4{VtuOutput::refresh_patches}

  // The patches of an element of degree 1 have one point per vertex of
  // their cell, where a nodal field is its value at the vertex (DataOut's
  // interpolation, whose other shape functions vanish there: 0 + value,
  // which also turns -0 into 0 as DataOut's sum does). The rows are those
  // of add_vtu_fields(): the nodal fields in its order, then the cell
  // fields. The points of curved cells, after the fields, stay. Where each
  // value comes from is found once per mesh (find_patch_sources()).
  template <int dim>
  void VtuOutput<dim>::refresh_patches(Pending &output) const
  {
    ReusablePatches<dim> &data_out = *output.data_out;
    if (data_out.patch_cells.empty())
      find_patch_sources(output);
    const std::vector<const FastVector *> vector_fields = {
      &output.displacement, &output.velocity, &output.friction_traction};
    const std::vector<const Vector<double> *> scalar_fields = {
      &output.status, &output.slip_rate, &output.friction_bound};
    std::vector<const Vector<double> *> cell_fields;
    for (const Vector<double> &component : output.stress)
      cell_fields.push_back(&component);
    cell_fields.push_back(&output.von_mises);

    auto dofs = data_out.point_dofs.cbegin();
    auto cell = data_out.patch_cells.cbegin();
    for (DataOutBase::Patch<dim> &patch : data_out.built_patches())
      {
        for (unsigned int v = 0; v < patch.data.n_cols(); ++v, dofs += dim + 1)
          {
            unsigned int row = 0;
            for (const FastVector *field : vector_fields)
              for (unsigned int d = 0; d < dim; ++d)
                patch.data(row++, v) = 0. + field->local_element(dofs[d]);
            for (const Vector<double> *field : scalar_fields)
              patch.data(row++, v) = 0. + (*field)(dofs[dim]);
            for (const Vector<double> *field : cell_fields)
              patch.data(row++, v) = (*field)(*cell);
          }
        ++cell;
      }
  }


  // The patches are DataOut's, one for each locally owned active cell in
  // order, with a point for each vertex. The three vector fields have the
  // layout of the displacement's ghosted copy.
  template <int dim>
  void VtuOutput<dim>::find_patch_sources(Pending &output) const
  {
    const DiscreteSpace<dim>          &space    = this->space();
    ReusablePatches<dim>              &data_out = *output.data_out;
    const Utilities::MPI::Partitioner &partitioner =
      *output.displacement.get_partitioner();
    const std::vector<DataOutBase::Patch<dim>> &patches =
      data_out.built_patches();
    std::vector<types::global_dof_index> dofs(space.fe.n_dofs_per_cell()),
      scalar_dofs(space.scalar_dof_handler.get_fe().n_dofs_per_cell());
    auto patch = patches.begin();
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          AssertThrow(patch != patches.end() &&
                        patch->data.n_cols() == cell->n_vertices(),
                      ExcInternalError());
          cell->get_dof_indices(dofs);
          typename DoFHandler<dim>::active_cell_iterator(
            &cell->get_triangulation(),
            cell->level(),
            cell->index(),
            &space.scalar_dof_handler)
            ->get_dof_indices(scalar_dofs);
          for (const unsigned int v : cell->vertex_indices())
            {
              for (unsigned int d = 0; d < dim; ++d)
                data_out.point_dofs.push_back(partitioner.global_to_local(
                  dofs[space.fe.component_to_system_index(d, v)]));
              data_out.point_dofs.push_back(scalar_dofs[v]);
            }
          data_out.patch_cells.push_back(cell->active_cell_index());
          ++patch;
        }
    AssertThrow(patch == patches.end(), ExcInternalError());
  }


  // @sect4{VtuOutput::write_vtu_piece}

  // This process's piece of the output, written into .partial/: the
  // output thread's work.
  template <int dim>
  void VtuOutput<dim>::write_vtu_piece(Pending           &output,
                                       const std::string &file) const
  {
    const DiscreteSpace<dim> &space    = this->space();
    DataOut<dim>             &data_out = *output.data_out;
    if (output.refresh)
      refresh_patches(output);
    else
      {
        data_out.build_patches(*space.mapping, space.fe.degree);
        data_out.clear_input_data_references();
      }

    DataOutBase::VtkFlags flags;
    flags.time              = output.time;
    flags.cycle             = output.step;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::ofstream stream(file);
    if (stream)
      data_out.write_vtu(stream);
    stream.flush();
    AssertThrow(stream,
                ExcMessage("Cannot write the VTU file '" + file +
                           "': " + std::strerror(errno) + "."));
  }


  // @sect4{VtuOutput::finish_vtu}

  // Atomic output: the pieces and the .pvtu record go to .partial/ and are
  // renamed into the output directory once all processes have written
  // them, the record last; the PVD is rewritten by rename. A run killed at
  // any point leaves only complete files, and the PVD lists only files
  // that exist.
  template <int dim>
  void VtuOutput<dim>::finish_vtu()
  {
    if (!pending_vtu)
      return;
    TimerOutput::Scope             t(this->computing_timer(), "Output");
    const std::shared_ptr<Pending> output = std::move(pending_vtu);
    output->written.get();
    if (this->space().fe.degree == 1)
      mesh_patches = output->data_out;
    const int ierr = MPI_Barrier(this->mpi_communicator());
    AssertThrowMPI(ierr);
    if (Utilities::MPI::this_mpi_process(this->mpi_communicator()) != 0)
      return;

    const std::string &directory = this->parameters().output.directory;
    const std::string  record =
      "solution_" + Utilities::int_to_string(output->step, 5) + ".pvtu";
    std::vector<std::string> pieces;
    for (unsigned int process = 0;
         process < Utilities::MPI::n_mpi_processes(this->mpi_communicator());
         ++process)
      pieces.push_back(vtu_piece_name(output->step, process));
    {
      std::ofstream stream(directory + "/.partial/" + record);
      output->data_out->write_pvtu_record(stream, pieces);
      stream.flush();
      AssertThrow(stream,
                  ExcMessage("Cannot write '" + directory + "/.partial/" +
                             record + "': " + std::strerror(errno) + "."));
    }
    for (const std::string &piece : pieces)
      std::filesystem::rename(directory + "/.partial/" + piece,
                              directory + "/" + piece);
    std::filesystem::rename(directory + "/.partial/" + record,
                            directory + "/" + record);
    pvd_records.emplace_back(output->time, record);
    write_pvd();
  }


  // @sect4{VtuOutput::drop_missing_records}

  // A resumed run lists in its PVD only the records whose files are still
  // there (a user may have deleted some to save space), and says which
  // it dropped.
  template <int dim>
  void VtuOutput<dim>::drop_missing_records()
  {
    const std::string       &directory = this->parameters().output.directory;
    std::vector<std::string> missing;
    std::vector<std::pair<double, std::string>> kept;
    for (const auto &record : pvd_records)
      if (std::filesystem::exists(directory + "/" + record.second))
        kept.push_back(record);
      else
        missing.push_back(record.second);
    if (missing.empty())
      return;
    this->pcout() << "Warning: " << missing.size()
                  << " VTU record(s) of solution.pvd are gone from '"
                  << directory << "' (the first: " << missing.front()
                  << "); the resumed run's solution.pvd lists the others."
                  << std::endl;
    pvd_records = kept;
  }


  // @sect4{VtuOutput::write_pvd}

  template <int dim>
  void VtuOutput<dim>::write_pvd() const
  {
    if (Utilities::MPI::this_mpi_process(this->mpi_communicator()) != 0)
      return;
    const std::string name =
      this->parameters().output.directory + "/solution.pvd";
    {
      std::ofstream pvd(name + ".tmp");
      DataOutBase::write_pvd_record(pvd, pvd_records);
      pvd.flush();
      AssertThrow(pvd,
                  ExcMessage("Cannot write '" + name +
                             ".tmp': " + std::strerror(errno) + "."));
    }
    std::filesystem::rename(name + ".tmp", name);
  }


  namespace
  {
    const PostprocessorRegistration<VtuOutput>
      registration("VTU output", 70, own_entries);
  }
} // namespace Contact
