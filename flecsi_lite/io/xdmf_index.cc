// The XDMF index of a snapshot series (see xdmf_index.hh): the files read back with serial HDF5
// and described as XDMF 2 temporal and spatial collections of polyvertex grids.
#include "flecsi_lite/io/xdmf_index.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/io/output_path.hh"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace flecsi_lite::io {

namespace {
// The root groups of an open file, in HDF5's name order.
std::vector<std::string> link_names(hid_t location) {
  std::vector<std::string> names;
  H5Literate(
    location, H5_INDEX_NAME, H5_ITER_INC, nullptr,
    [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
      static_cast<std::vector<std::string>*>(out)->push_back(name);
      return 0;
    },
    &names);
  return names;
}

bool is_object(hid_t location, const std::string& name, H5O_type_t type) {
  if (H5Lexists(location, name.c_str(), H5P_DEFAULT) <= 0) return false;
  H5O_info_t info;
#if H5_VERSION_GE(1, 12, 0)
  if (H5Oget_info_by_name3(location, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) return false;
#else
  if (H5Oget_info_by_name(location, name.c_str(), &info, H5P_DEFAULT) < 0) return false;
#endif
  return info.type == type;
}

// A dataset of N or N x C numbers; empty name when it is anything else.
xdmf_array describe_dataset(hid_t group, const std::string& name) {
  xdmf_array array;
  auto dataset = dataset_handle(H5Dopen2(group, name.c_str(), H5P_DEFAULT));
  if (!dataset) return array;
  auto space = dataspace_handle(H5Dget_space(dataset.get()));
  auto type = datatype_handle(H5Dget_type(dataset.get()));
  const int rank = space ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 1 || rank > 2 || !type) return array;
  hsize_t extent[2] = {0, 1};
  H5Sget_simple_extent_dims(space.get(), extent, nullptr);
  const H5T_class_t kind = H5Tget_class(type.get());
  if (kind == H5T_FLOAT)
    array.number_type = "Float";
  else if (kind == H5T_INTEGER)
    array.number_type = H5Tget_sign(type.get()) == H5T_SGN_NONE ? "UInt" : "Int";
  else
    return array;
  array.name = name;
  array.rows = extent[0];
  array.columns = rank == 2 ? static_cast<int>(extent[1]) : 1;
  array.precision = static_cast<int>(H5Tget_size(type.get()));
  return array;
}

double read_time(hid_t file, const snapshot_series_layout& layout, const std::string& path) {
  const std::string what = "attribute " + layout.time_group + "/" + layout.time_attribute + " of '" + path + "'";
  auto group = group_handle(H5Gopen2(file, layout.time_group.c_str(), H5P_DEFAULT));
  if (!group || H5Aexists(group.get(), layout.time_attribute.c_str()) <= 0) throw missing_attribute_error("no " + what);
  auto attribute = attribute_handle(H5Aopen(group.get(), layout.time_attribute.c_str(), H5P_DEFAULT));
  auto space = dataspace_handle(H5Aget_space(attribute.get()));
  // One number, scalar or (as GADGET and SWIFT write it) an array of one.
  if (!space || H5Sget_simple_extent_npoints(space.get()) != 1)
    throw element_type_error(what + " is not a single number");
  double time = 0;
  if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &time) < 0)
    throw element_type_error("cannot read " + what + " as a real" + hdf5_reason());
  return time;
}

std::string relative_to_folder_of(const std::string& index_path, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(index_path).parent_path();
  return fs::absolute(path).lexically_normal().lexically_relative(folder.lexically_normal()).generic_string();
}

// Text safe inside an XML attribute or element.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string data_item(const xdmf_array& array, const std::string& file, const std::string& group) {
  std::ostringstream item;
  item << "<DataItem Dimensions=\"" << array.rows;
  if (array.columns > 1) item << " " << array.columns;
  item << "\" NumberType=\"" << array.number_type << "\" Precision=\"" << array.precision << "\" Format=\"HDF\">"
       << escaped(file) << ":/" << escaped(group) << "/" << escaped(array.name) << "</DataItem>";
  return item.str();
}
}  // namespace

snapshot_description describe_snapshot(const std::string& path, const snapshot_series_layout& layout) {
  hdf5_quiet_scope quiet;
  if (!std::filesystem::is_regular_file(path)) throw file_error("no snapshot file '" + path + "'");
  auto file = file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file) throw file_error("cannot open snapshot '" + path + "'" + hdf5_reason());
  snapshot_description description;
  description.time = read_time(file.get(), layout, path);
  for (const std::string& name : link_names(file.get())) {
    if (!is_object(file.get(), name, H5O_TYPE_GROUP)) continue;
    auto group = group_handle(H5Gopen2(file.get(), name.c_str(), H5P_DEFAULT));
    if (!group || !is_object(group.get(), layout.coordinates, H5O_TYPE_DATASET)) continue;
    xdmf_grid grid{name, 0, {}};
    const xdmf_array coordinates = describe_dataset(group.get(), layout.coordinates);
    if (coordinates.name.empty() || coordinates.columns != 3) continue;
    grid.points = coordinates.rows;
    grid.arrays.push_back(coordinates);
    for (const std::string& member : link_names(group.get())) {
      if (member == layout.coordinates || !is_object(group.get(), member, H5O_TYPE_DATASET)) continue;
      const xdmf_array array = describe_dataset(group.get(), member);
      if (!array.name.empty() && array.rows == grid.points && (array.columns == 1 || array.columns == 3))
        grid.arrays.push_back(array);
    }
    description.grids.push_back(std::move(grid));
  }
  return description;
}

std::string xdmf_text(const std::vector<snapshot_description>& snapshots, const std::vector<std::string>& file_names) {
  std::ostringstream text;
  text << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
       << "<Xdmf xmlns:xi=\"http://www.w3.org/2003/XInclude\" Version=\"2.1\">\n<Domain>\n"
       << "<Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    char time[40];
    std::snprintf(time, sizeof time, "%.17g", snapshots[k].time);
    text << "<Grid Name=\"" << escaped(file_names[k]) << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
         << "  <Time Type=\"Single\" Value=\"" << time << "\"/>\n";
    for (const xdmf_grid& grid : snapshots[k].grids) {
      text << "  <Grid Name=\"" << escaped(grid.group) << "\" GridType=\"Uniform\">\n"
           << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << grid.points << "\"/>\n"
           << "    <Geometry GeometryType=\"XYZ\">\n      " << data_item(grid.arrays[0], file_names[k], grid.group)
           << "\n    </Geometry>\n";
      for (std::size_t a = 1; a < grid.arrays.size(); ++a) {
        const xdmf_array& array = grid.arrays[a];
        text << "    <Attribute Name=\"" << escaped(array.name) << "\" AttributeType=\""
             << (array.columns == 1 ? "Scalar" : "Vector") << "\" Center=\"Node\">\n      "
             << data_item(array, file_names[k], grid.group) << "\n    </Attribute>\n";
      }
      text << "  </Grid>\n";
    }
    text << "</Grid>\n";
  }
  text << "</Grid>\n</Domain>\n</Xdmf>\n";
  return text.str();
}

void write_xdmf_index(MPI_Comm comm, const std::string& index_path, const std::vector<std::string>& paths,
                      const snapshot_series_layout& layout) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  agree(comm, [&] {
    if (rank != 0) return;
    std::vector<snapshot_description> snapshots;
    std::vector<std::string> names;
    for (const std::string& path : paths) {
      snapshots.push_back(describe_snapshot(path, layout));
      names.push_back(relative_to_folder_of(index_path, path));
    }
    write_text_file(index_path, xdmf_text(snapshots, names), "XDMF index");
  });
}

}  // namespace flecsi_lite::io
