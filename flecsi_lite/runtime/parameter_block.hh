// Parameters declared once: a parameter_block binds each key of a settings struct to the member it
// fills, so that name, type, default (the struct's own default member initializer), bounds and
// help are written in one line, and read() fills every member (in the spirit of FleCSI's
// program_option<T>, declared next to its use).
//
//   parameter_block<physics_settings> physics;
//   physics.real("courant", &physics_settings::courant, "Courant factor").greater_than(0).at_most(1);
//   physics.real("gamma", member(&physics_settings::eos, &equation_of_state::ideal, &ideal_gas::gamma),
//                "adiabatic index").greater_than(1);
//   physics.choice("kernel", &physics_settings::kernel, kernel_names, "smoothing kernel");
//   physics.declare(schema);                                  // the keys, into an app's schema
//   physics_settings s = physics.read(parameters::load(schema, "run.par"));
//
// Vocabulary: a *member* is where a key's value lives in the struct: a pointer to a data member,
// a chain of them (member(&a::b, &b::c)) for nested structs, or a callable `T& (Settings&)`.
#pragma once

#include "flecsi_lite/runtime/name_table.hh"
#include "flecsi_lite/runtime/parameters.hh"

#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace flecsi_lite::runtime {

/// A chain of pointers to data members: member(&a::b, &b::c)(x) is x.b.c.
template<class... Pointers>
struct member_chain {
  std::tuple<Pointers...> pointers;

  template<class Object>
  decltype(auto) operator()(Object& object) const {
    return walk<0>(object);
  }

 private:
  template<std::size_t I, class Object>
  decltype(auto) walk(Object& object) const {
    if constexpr (I == sizeof...(Pointers))
      return (object);
    else
      return walk<I + 1>(object.*std::get<I>(pointers));
  }
};

template<class... Pointers>
member_chain<Pointers...> member(Pointers... pointers) {
  static_assert(sizeof...(Pointers) > 0 && (std::is_member_object_pointer_v<Pointers> && ...),
                "member() takes pointers to data members");
  return {std::tuple<Pointers...>(pointers...)};
}

namespace detail {
/// The member of `settings` that `member` designates, as a reference.
template<class Settings, class Member>
decltype(auto) reach(Settings& settings, const Member& member) {
  if constexpr (std::is_member_object_pointer_v<Member>)
    return (settings.*member);
  else
    return member(settings);
}
template<class Settings, class Member>
using member_type =
  std::remove_cv_t<std::remove_reference_t<decltype(reach(std::declval<Settings&>(), std::declval<const Member&>()))>>;
}  // namespace detail

/// The keys of one settings struct, each bound to its member. Keys are declared in order; each
/// declaring function returns the key's parameter_declaration, so bounds chain on it.
template<class Settings>
class parameter_block {
 public:
  /// `defaults` gives every key its default (by default, the struct's member initializers).
  explicit parameter_block(Settings defaults = Settings{}) : defaults_(std::move(defaults)) {}

  template<class Member>
  parameter_declaration& real(const std::string& name, Member member, const std::string& description) {
    using T = detail::member_type<Settings, Member>;
    static_assert(std::is_floating_point_v<T>, "a real key fills a floating-point member");
    return bind<T>(schema_.real(name, description), name, member);
  }
  template<class Member>
  parameter_declaration& integer(const std::string& name, Member member, const std::string& description) {
    using T = detail::member_type<Settings, Member>;
    static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>, "an integer key fills an integral member");
    return bind<T>(schema_.integer(name, description), name, member);
  }
  template<class Member>
  parameter_declaration& boolean(const std::string& name, Member member, const std::string& description) {
    static_assert(std::is_same_v<detail::member_type<Settings, Member>, bool>, "a boolean key fills a bool member");
    return bind<bool>(schema_.boolean(name, description), name, member);
  }
  template<class Member>
  parameter_declaration& string(const std::string& name, Member member, const std::string& description) {
    static_assert(std::is_same_v<detail::member_type<Settings, Member>, std::string>,
                  "a string key fills a std::string member");
    return bind<std::string>(schema_.string(name, description), name, member);
  }
  template<class Member>
  parameter_declaration& real_list(const std::string& name, Member member, const std::string& description) {
    static_assert(std::is_same_v<detail::member_type<Settings, Member>, std::vector<double>>,
                  "a list-of-reals key fills a std::vector<double> member");
    return bind<std::vector<double>>(schema_.real_list(name, description), name, member);
  }

  /// A key whose allowed values are the names of `table`; it fills an enum member.
  template<class Member, class Enum>
  parameter_declaration& choice(const std::string& name, Member member, const name_table<Enum>& table,
                                const std::string& description) {
    static_assert(std::is_same_v<detail::member_type<Settings, Member>, Enum>,
                  "a choice key fills a member of its name table's enum");
    auto& declaration = schema_.choice(name, table.names(), description);
    declaration.default_value(table.name(detail::reach(defaults_, member)));
    readers_.push_back([name, member, table](const parameters& p, Settings& s) {
      detail::reach(s, member) = table.value(p.get<std::string>(name));
    });
    return declaration;
  }

  /// A file name: the text "none" stands for the empty name (no file), in both directions.
  template<class Member>
  parameter_declaration& file(const std::string& name, Member member, const std::string& description) {
    static_assert(std::is_same_v<detail::member_type<Settings, Member>, std::string>,
                  "a file key fills a std::string member");
    const std::string& fallback = detail::reach(defaults_, member);
    auto& declaration = schema_.string(name, description).default_value(fallback.empty() ? "none" : fallback);
    readers_.push_back([name, member](const parameters& p, Settings& s) {
      std::string text = p.get<std::string>(name);
      detail::reach(s, member) = text == "none" ? std::string() : std::move(text);
    });
    return declaration;
  }

  /// A rule on the whole settings, checked by read() after every member is filled (e.g. keys that
  /// contradict each other); it throws parameter_error saying what is wrong.
  parameter_block& check(std::function<void(const Settings&)> rule) {
    checks_.push_back(std::move(rule));
    return *this;
  }

  /// Adds this block's keys to `schema`, after those it has.
  void declare(parameter_schema& schema) const { schema.add(schema_); }
  /// The defaults, then every key of this block from `p`, then the checks.
  Settings read(const parameters& p) const {
    Settings settings = defaults_;
    for (const auto& reader : readers_) reader(p, settings);
    for (const auto& rule : checks_) rule(settings);
    return settings;
  }
  const parameter_schema& schema() const { return schema_; }
  const Settings& defaults() const { return defaults_; }

 private:
  template<class T, class Member>
  parameter_declaration& bind(parameter_declaration& declaration, const std::string& name, const Member& member) {
    declaration.default_value(detail::reach(defaults_, member));
    readers_.push_back([name, member](const parameters& p, Settings& s) { detail::reach(s, member) = p.get<T>(name); });
    return declaration;
  }

  Settings defaults_;
  parameter_schema schema_;
  std::vector<std::function<void(const parameters&, Settings&)>> readers_;
  std::vector<std::function<void(const Settings&)>> checks_;
};

}  // namespace flecsi_lite::runtime
