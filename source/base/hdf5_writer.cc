#include <greentread/base/exceptions.h>
#include <greentread/base/hdf5_writer.h>

#include <functional>

namespace greentread
{
  namespace base
  {
    namespace
    {
      /// Closes an HDF5 handle when the scope ends.
      struct Handle
      {
        hid_t                        id;
        std::function<herr_t(hid_t)> close;
        ~Handle()
        {
          if (id >= 0)
            close(id);
        }
      };
    } // namespace



    Hdf5Writer::Hdf5Writer(const std::string &file_)
        : file_name(file_)
    {
      // No times on the root group either (a file creation property list
      // is a group's).
      const Handle fcpl{H5Pcreate(H5P_FILE_CREATE), H5Pclose};
      if (fcpl.id < 0 || H5Pset_obj_track_times(fcpl.id, false) < 0)
        throw NumericalError("HDF5 file '" + file_name + "': cannot make its property list");
      file = H5Fcreate(file_name.c_str(), H5F_ACC_TRUNC, fcpl.id, H5P_DEFAULT);
      if (file < 0)
        throw InputError("HDF5 file '" + file_name + "' cannot be created");
    }



    Hdf5Writer::~Hdf5Writer()
    {
      if (file >= 0)
        H5Fclose(file);
    }



    void
    Hdf5Writer::set_attribute(const std::string &name, const std::string &value)
    {
      const Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
      const Handle space{H5Screate(H5S_SCALAR), H5Sclose};
      if (type.id < 0 || space.id < 0 || H5Tset_cset(type.id, H5T_CSET_UTF8) < 0 ||
          H5Tset_size(type.id, H5T_VARIABLE) < 0)
        throw NumericalError("HDF5 file '" + file_name + "': cannot make attribute '" + name + "'");
      const Handle attribute{
        H5Acreate2(file, name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
      const char *text = value.c_str();
      if (attribute.id < 0 || H5Awrite(attribute.id, type.id, &text) < 0)
        throw InputError("HDF5 file '" + file_name + "': cannot write attribute '" + name + "'");
    }



    void
    Hdf5Writer::write_dataset(const std::string          &name,
                              const std::vector<hsize_t> &dimensions,
                              const void                 *values,
                              const std::size_t           count,
                              const Type                  type)
    {
      hsize_t size = 1;
      for (const hsize_t d : dimensions)
        size *= d;
      if (size != count)
        throw NumericalError("HDF5 file '" + file_name + "': dataset '" + name + "' of " +
                             std::to_string(size) + " values given " + std::to_string(count));
      Handle datatype{-1, H5Tclose};
      if (type == Type::complex)
        {
          datatype.id = H5Tcreate(H5T_COMPOUND, sizeof(std::complex<double>));
          if (datatype.id < 0 || H5Tinsert(datatype.id, "r", 0, H5T_NATIVE_DOUBLE) < 0 ||
              H5Tinsert(datatype.id, "i", sizeof(double), H5T_NATIVE_DOUBLE) < 0)
            throw NumericalError("HDF5 file '" + file_name + "': cannot make a complex type");
        }
      else
        datatype.id = H5Tcopy(type == Type::real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT);
      const Handle dcpl{H5Pcreate(H5P_DATASET_CREATE), H5Pclose};
      const Handle space{H5Screate_simple(int(dimensions.size()), dimensions.data(), nullptr),
                         H5Sclose};
      if (datatype.id < 0 || dcpl.id < 0 || space.id < 0 ||
          H5Pset_obj_track_times(dcpl.id, false) < 0)
        throw NumericalError("HDF5 file '" + file_name + "': cannot make dataset '" + name + "'");
      const Handle dataset{
        H5Dcreate2(file, name.c_str(), datatype.id, space.id, H5P_DEFAULT, dcpl.id, H5P_DEFAULT),
        H5Dclose};
      if (dataset.id < 0 || (count > 0 && H5Dwrite(dataset.id, datatype.id, H5S_ALL, H5S_ALL,
                                                   H5P_DEFAULT, values) < 0))
        throw InputError("HDF5 file '" + file_name + "': cannot write dataset '" + name + "'");
    }
  } // namespace base
} // namespace greentread
