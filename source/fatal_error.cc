#include <deal.II/base/mpi.h>

#include <ddcontact/fatal_error.h>
#include <ddcontact/interruption.h>
#include <ddcontact/iteration_errors.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameter_tools.h>

#include <chrono>
#include <iostream>
#include <map>
#include <thread>
#include <vector>

namespace ddcontact
{
  FatalError::FatalError()
  {
    MPI_Comm_dup(MPI_COMM_WORLD, &communicator);
    rank        = dealii::Utilities::MPI::this_mpi_process(communicator);
    n_processes = dealii::Utilities::MPI::n_mpi_processes(communicator);
  }

  FatalError::~FatalError()
  {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized && communicator != MPI_COMM_NULL)
      MPI_Comm_free(&communicator);
  }

  std::pair<int, std::string>
  FatalError::classify(const std::exception_ptr &error)
  {
    try
    {
      std::rethrow_exception(error);
    }
    // The most derived classes first: TargetNotReachedError and
    // NotConvergedError are also DivergenceErrors of sorts.
    catch (const TargetNotReachedError &e)
    {
      return {exit_codes::target_not_reached, e.what()};
    }
    catch (const DivergenceError &e)
    {
      return {exit_codes::iteration_failed, e.what()};
    }
    catch (const InterruptedError &e)
    {
      return {exit_codes::interrupted, e.what()};
    }
    catch (const WriteError &e)
    {
      return {exit_codes::write_failed, e.what()};
    }
    catch (const OutOfMemoryError &e)
    {
      return {exit_codes::out_of_memory, e.what()};
    }
    catch (const std::bad_alloc &)
    {
      return {exit_codes::out_of_memory,
              "out of memory; refine less (Initial refinement, Max cells) or "
              "run on more processes"};
    }
    catch (const InputError &e)
    {
      return {exit_codes::bad_input, e.what()};
    }
    catch (const std::exception &e)
    {
      return {exit_codes::internal_error, e.what()};
    }
    catch (...)
    {
      return {exit_codes::internal_error, "an unknown exception"};
    }
  }

  int
  FatalError::report(const std::exception_ptr &error) const
  {
    const auto [code, message] = classify(error);
    if (n_processes == 1)
    {
      std::cerr << "ddcontact: error: " << message << std::endl;
      return code;
    }

    // Do the others meet an error too? Only this communicator's barrier
    // can complete here, whatever the others are waiting in.
    MPI_Request request;
    MPI_Ibarrier(communicator, &request);
    int        all_here = 0;
    const auto start    = std::chrono::steady_clock::now();
    while (true)
    {
      MPI_Test(&request, &all_here, MPI_STATUS_IGNORE);
      if (all_here || std::chrono::duration<double>(
                        std::chrono::steady_clock::now() - start)
                          .count() > seconds_to_wait)
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!all_here)
    {
      std::cerr << "ddcontact: error on process " << rank << " of "
                << n_processes << ": " << message << std::endl;
      MPI_Abort(MPI_COMM_WORLD, code);
    }

    // Every process is here: each distinct message once, with the
    // processes that met it when they are not all.
    const auto all = dealii::Utilities::MPI::gather(
      communicator, std::make_pair(code, message), 0);
    if (rank == 0)
    {
      std::map<std::string, std::vector<unsigned int>> by_message;
      for (unsigned int p = 0; p < all.size(); ++p)
        by_message[all[p].second].push_back(p);
      for (const auto &[text, processes] : by_message)
      {
        std::cerr << "ddcontact: error";
        if (processes.size() < n_processes)
        {
          std::cerr << " on process" << (processes.size() > 1 ? "es " : " ");
          for (unsigned int i = 0; i < processes.size(); ++i)
            std::cerr << (i > 0 ? ", " : "") << processes[i];
        }
        std::cerr << ": " << text << std::endl;
      }
    }
    return dealii::Utilities::MPI::max(code, communicator);
  }
} // namespace ddcontact
