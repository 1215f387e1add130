#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/modal_sources_digest.h>
#include <greentread/synthesis/harmonic_modes.h>
#include <greentread/synthesis/mode_stage.h>
#include <greentread/synthesis/ring_modes.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace greentread
{
  namespace synthesis
  {
    std::string
    mode_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key)
    {
      std::ostringstream key;
      key << green_key << "\n--- modes ---\nsources digest " << GREENTREAD_MODAL_SOURCES_DIGEST
          << '\n';
      for (const auto &[path, value] :
           base::ParameterRecord::from(prm, "", {"Patch model"}).entries)
        if (path == "Patch model/Mode cutoff")
          key << path << " = " << value << '\n';
      return key.str();
    }



    synthesis::ModeSynthesis
    run_mode_stage(const ModeStageInputs               &inputs,
                   const base::FrequencyResponseMatrix &green,
                   const std::filesystem::path         &file,
                   const std::string                   &key,
                   const base::ParameterRecord         &record,
                   const bool                           reuse,
                   const bool                           print_timings,
                   const MPI_Comm                       comm,
                   synthesis::ModalLines               *lines)
    {
      synthesis::ModeSynthesis synthesis;
      if (reuse && synthesis::read_modal_model_key(file.string()) == key &&
          base::read_saved_stage(file, [&] {
            synthesis = synthesis::read_modal_model(file.string());
          }))
        {
          std::cout << "Reusing " << file.string() << ": same Green's functions and mode cut-off\n";
          return synthesis;
        }
      const auto t0 = std::chrono::steady_clock::now();
      std::cout << "Stage modal: the ring's own modes up to " << format_number(inputs.cutoff_hz)
                << " Hz, per circumferential "
                << (inputs.harmonic ? "harmonic of the section\n" : "wavenumber\n");
      std::unique_ptr<periodic::InflatedTyre> built;
      if (inputs.tyre == nullptr)
        built = std::make_unique<periodic::InflatedTyre>(
          inputs.geometry, inputs.materials, inputs.inflation, inputs.patch, inputs.harmonic);
      const periodic::InflatedTyre &tyre = inputs.tyre ? *inputs.tyre : *built;
      const unsigned int            P    = green.n_points();
      if (tyre.patch.points.size() != P)
        throw NumericalError("modal stage: the tyre has " +
                             std::to_string(tyre.patch.points.size()) +
                             " contact points, the Green's functions " + std::to_string(P));
      for (unsigned int p = 0; p < P; ++p)
        if (std::abs(tyre.patch.points[p].x - green.points[p][0]) > 1e-9 ||
            std::abs(tyre.patch.points[p].y - green.points[p][1]) > 1e-9 ||
            std::abs(tyre.patch.points[p].radius - green.points[p][2]) > 1e-9)
          throw NumericalError("modal stage: contact point " + std::to_string(p) +
                               " is not where the Green's functions have it");

      ModeSearch search;
      search.cutoff         = 2. * M_PI * inputs.cutoff_hz;
      const RingModes modes = tyre.harmonic ?
                                harmonic_ring_modes(*tyre.harmonic, search.cutoff, comm, true) :
                                ring_modes(tyre.periodic_cell, tyre.patch, search, comm, true);

      // G_r from the static line (the direct solve at 0 Hz), its relaxation
      // from the others.
      synthesis            = synthesis::synthesise(modes.omega, modes.damping_ratio, modes.shapes,
                                                   modes.shapes_imag, green, lines);
      synthesis.wavenumber = modes.wavenumber;
      for (std::size_t k = 0; k < modes.branches.size(); ++k)
        {
          synthesis.dispersion.frequency_hz.push_back(modes.branches[k] / (2. * M_PI));
          synthesis.dispersion.damping_ratio.push_back(modes.branch_damping[k]);
        }
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        synthesis::write_modal_model(file, synthesis, record, key);
      const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - t0;
      std::cout << "  " << synthesis.n_modes() << " ring modes from " << modes.branches.size()
                << (tyre.harmonic ? " harmonics (" : " wavenumbers (") << modes.n_solves
                << " sparse solves, largest relative residual "
                << format_printf("%.2g", modes.max_residual) << "), coupled by the damping";
      if (modes.uncoupled > 0)
        std::cout << " except at " << modes.uncoupled
                  << (tyre.harmonic ? " harmonics" : " wavenumbers")
                  << " (a pole near critical damping: diagonal damping there)";
      if (print_timings)
        std::cout << ", " << format_printf("%.3g", seconds.count()) << " s";
      std::cout << '\n';
      return synthesis;
    }
  } // namespace synthesis
} // namespace greentread
