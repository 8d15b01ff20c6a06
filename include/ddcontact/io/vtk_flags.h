#ifndef ddcontact_io_vtk_flags_h
#define ddcontact_io_vtk_flags_h

#include <deal.II/base/data_out_base.h>

namespace ddcontact
{
  /**
   * The flags of every VTU file the code writes (bodies and contact
   * zones). zlib's fastest level: deal.II's default, its best compression,
   * took 4 of the 10 s of prm/hertz_large.prm for files 2 % smaller.
   */
  inline dealii::DataOutBase::VtkFlags
  vtk_flags()
  {
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    return flags;
  }
} // namespace ddcontact

#endif
