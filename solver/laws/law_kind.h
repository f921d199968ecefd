// The contact laws ivv names: one enumerator per built-in law, in the order of BuiltinLaws
// (solver/laws/law_registry.h), then `expression`, a law typed on the command line. Each built-in
// law states its own enumerator (its member `kind`), and law_registry.cc checks at compile time
// that entry I of BuiltinLaws is LawKind number I: no list of names is kept beside this one.
#pragma once

namespace ivv {

enum class LawKind { hertz, elastoplastic, linearized, hunt_crossley, expression };

}  // namespace ivv
