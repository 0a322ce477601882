// Storage of one field on one topology instance: a Kokkos view of owned entities followed by
// ghost entities (Structure of Arrays: one view per field). The type-erased interface lets the
// framework resize, reorder, pack and unpack every field without knowing its type.
#pragma once

#include "flecsi_lite/util/kokkos.hh"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace flecsi_lite::data {

class field_storage_base {
 public:
  explicit field_storage_base(std::string name) : name_(std::move(name)) {}
  virtual ~field_storage_base() = default;

  const std::string& name() const { return name_; }
  virtual std::size_t element_size() const = 0;
  virtual const std::type_info& element_type() const = 0;
  virtual std::size_t size() const = 0;

  /// New size; the first min(old, new) elements keep their values, new ones are value-initialized.
  virtual void resize(std::size_t n) = 0;
  /// new[i] = old[order[i]] for i < order.size(); the size becomes order.size() + keep_tail
  /// where the last keep_tail elements are left value-initialized (room for ghosts).
  virtual void gather(const std::vector<std::size_t>& order, std::size_t tail) = 0;
  /// Copies the elements at `indices` into `out` (element_size() bytes each).
  virtual void pack(const std::size_t* indices, std::size_t count, std::byte* out) const = 0;
  /// Copies `count` elements from `in` to positions first, first+1, ...
  virtual void unpack(const std::byte* in, std::size_t first, std::size_t count) = 0;
  /// Copies the `count` elements from position `first` into `out` (unpack's inverse).
  virtual void pack_range(std::size_t first, std::size_t count, std::byte* out) const = 0;
  /// Copies into `out` the elements at `indices` whose bytes differ from `previous` (`count`
  /// elements, then overwritten with the current ones), or every element when `compare` is
  /// false, and marks them in `mask` (bit i % 8 of byte i / 8, for element i); returns the bytes
  /// written to `out`.
  virtual std::size_t pack_changed(const std::size_t* indices, std::size_t count, bool compare, std::byte* previous,
                                   std::uint8_t* mask, std::byte* out) const = 0;
  /// pack_changed's inverse: the marked elements of positions first, ..., first + count - 1 take
  /// the values in `in`, in order; returns the bytes read.
  virtual std::size_t unpack_marked(const std::uint8_t* mask, const std::byte* in, std::size_t first,
                                    std::size_t count) = 0;

 private:
  std::string name_;
};

/// Packs the values at `indices` of several fields into one message: the first field's values,
/// then the next field's (element_size() bytes each).
inline void pack_fields(const std::vector<field_storage_base*>& fields, const std::vector<std::size_t>& indices,
                        std::byte* out) {
  for (const auto* f : fields) {
    f->pack(indices.data(), indices.size(), out);
    out += indices.size() * f->element_size();
  }
}
/// Unpacks a message of pack_fields into positions first, ..., first + count - 1 of each field.
inline void unpack_fields(const std::vector<field_storage_base*>& fields, const std::byte* in, std::size_t first,
                          std::size_t count) {
  for (auto* f : fields) {
    f->unpack(in, first, count);
    in += count * f->element_size();
  }
}

template<class T>
class field_storage final : public field_storage_base {
  static_assert(std::is_trivially_copyable_v<T>, "field values are copied as bytes");

 public:
  using view_type = Kokkos::View<T*, memory_space>;

  field_storage(std::string name, std::size_t n)
      : field_storage_base(std::move(name)), view_(Kokkos::view_alloc(this->name()), n) {}

  view_type view() const { return view_; }
  std::size_t element_size() const override { return sizeof(T); }
  const std::type_info& element_type() const override { return typeid(T); }
  std::size_t size() const override { return view_.extent(0); }

  void resize(std::size_t n) override { Kokkos::resize(view_, n); }

  // The gathered values are written once: no zero-fill before them (a second pass over memory,
  // and the first touch of its pages); the tail, filled later, starts at zero as before.
  void gather(const std::vector<std::size_t>& order, std::size_t tail) override {
    const std::size_t count = order.size();
    view_type result(Kokkos::view_alloc(Kokkos::WithoutInitializing, name()), count + tail);
    auto source = view_;
    const std::size_t* o = order.data();
    Kokkos::parallel_for(
      "flecsi_lite::gather", Kokkos::RangePolicy<execution_space>(0, count + tail),
      KOKKOS_LAMBDA(std::size_t i) { result(i) = i < count ? source(o[i]) : T{}; });
    Kokkos::fence();
    view_ = result;
  }

  void pack(const std::size_t* indices, std::size_t count, std::byte* out) const override {
    T* values = reinterpret_cast<T*>(out);
    for (std::size_t i = 0; i < count; ++i) std::memcpy(values + i, &view_(indices[i]), sizeof(T));
  }

  void unpack(const std::byte* in, std::size_t first, std::size_t count) override {
    if (count) std::memcpy(view_.data() + first, in, count * sizeof(T));
  }

  void pack_range(std::size_t first, std::size_t count, std::byte* out) const override {
    if (count) std::memcpy(out, view_.data() + first, count * sizeof(T));
  }

  std::size_t pack_changed(const std::size_t* indices, std::size_t count, bool compare, std::byte* previous,
                           std::uint8_t* mask, std::byte* out) const override {
    std::byte* const start = out;
    std::fill(mask, mask + (count + 7) / 8, std::uint8_t(0));
    for (std::size_t i = 0; i < count; ++i) {
      const T& value = view_(indices[i]);
      std::byte* last = previous + i * sizeof(T);
      if (compare && std::memcmp(&value, last, sizeof(T)) == 0) continue;
      std::memcpy(last, &value, sizeof(T));
      std::memcpy(out, &value, sizeof(T));
      out += sizeof(T);
      mask[i / 8] |= std::uint8_t(1u << (i % 8));
    }
    return std::size_t(out - start);
  }

  std::size_t unpack_marked(const std::uint8_t* mask, const std::byte* in, std::size_t first,
                            std::size_t count) override {
    const std::byte* const start = in;
    T* values = view_.data() + first;
    for (std::size_t i = 0; i < count; i += 8) {
      if (mask[i / 8] == 0) continue;               // most entries of a copy that sends few
      if (mask[i / 8] == 0xff && i + 8 <= count) {  // most entries of a copy that sends all
        std::memcpy(values + i, in, 8 * sizeof(T));
        in += 8 * sizeof(T);
        continue;
      }
      for (std::size_t j = i; j < std::min(count, i + 8); ++j)
        if ((mask[j / 8] >> (j % 8)) & 1u) {
          std::memcpy(values + j, in, sizeof(T));
          in += sizeof(T);
        }
    }
    return std::size_t(in - start);
  }

 private:
  view_type view_;
};

// The element types of most fields, compiled once in field_instances.cc.
extern template class field_storage<double>;
extern template class field_storage<std::uint64_t>;
extern template class field_storage<std::int64_t>;
extern template class field_storage<std::array<double, 1>>;
extern template class field_storage<std::array<double, 2>>;
extern template class field_storage<std::array<double, 3>>;

}  // namespace flecsi_lite::data
