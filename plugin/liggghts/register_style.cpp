// Access to the private Modify::fix_map through an explicit instantiation (see register_style.h).
// Kept in one translation unit: the friend function is defined (inline) only where it is instantiated.
#include "register_style.h"

namespace brash::liggghts {
namespace {

struct ModifyFixMapTag {
  using type = FixMap* LAMMPS_NS::Modify::*;
  friend type fix_map_member(ModifyFixMapTag);
};

template <typename Tag, typename Tag::type Member>
struct ExposeMember {
  friend typename Tag::type fix_map_member(Tag) { return Member; }
};

template struct ExposeMember<ModifyFixMapTag, &LAMMPS_NS::Modify::fix_map>;

}  // namespace

void register_fix_creator(LAMMPS_NS::LAMMPS* lmp, const std::string& style, FixCreatorFn creator) {
  FixMap* map = lmp->modify->*fix_map_member(ModifyFixMapTag{});
  (*map)[style] = creator;
}

}  // namespace brash::liggghts
