#pragma once
// Contact forces (CONTACT, docs/contact.md) at one evaluation of the dynamics: the
// shapes of ContactGeometry are moved to the bodies' poses (Data::X_wb), the pairs
// whose bounding boxes meet taken from a list of those that may touch (made by FCL's
// dynamic AABB tree over the ground's and the scene's shapes and bounding boxes between
// the moving ones, each moving box grown by a margin, and made again only when a box
// leaves its margin), their contact points measured (FCL's narrow phase, our sampled
// round solids), and each point's force added to the bodies' loads Data::fext
// (world axes, moment about the body frame's origin: dynamics/applied_forces.h).
//
// The law, per pair of solids with n contact points and the mass m_eff it moves
// (m_a·m_b/(m_a + m_b); the ground's is infinite), per point:
//   normal:     N = max(0, S + clamp(−c·v_n, ±kDamperCap·S)), S = k·min(d, depthCap),
//               k = m_eff·ω²/n, c = 2ζ·m_eff·ω/n (d the depth, v_n the separating speed;
//               ζ from the restitution e, contact_geometry.h);
//   tangential: a spring–damper between the two solids' material points that met
//               (the anchor, State::contacts): F_t = −k·s_t − c_t·v_t, c_t = 2·m_eff·ω/n,
//               held to |F_t| ≤ μ·N (slip). Without an anchor (a new contact) s_t = 0.
// At each step's end updateContactAnchors() keeps the anchors of the contacts that
// stuck, and moves those that slipped to where the spring carries μ·N: a resting
// body stays where it is (no creep), a sliding one feels μ·N.

#include "solver/core/contact.h"
#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

#include <memory>
#include <vector>

namespace solver {

/// The per-thread scratch (FCL objects and broad phase) for `geometry`.
std::unique_ptr<ContactScratch> makeContactScratch(const ContactGeometry& geometry);

/// Finds the contacts at the kinematics in `data` (X_wb, vel, omega) and adds their
/// loads to data.fext; data.contacts lists them. Uses `state.contacts` (anchors).
/// Nothing without model.contact. No allocation once warmed up (capacity kMaxContacts).
void applyContacts(const Model& model, const State& state, Data& data);

/// The anchors for the next step from the contacts of the evaluation in `data`
/// (at a step's end): into `anchors` (capacity kMaxContacts).
void updateContactAnchors(const Model& model, Data& data, std::vector<ContactAnchor>& anchors);

/// A profiling clock for `padrob bench`'s contact_us: while on, applyContacts and
/// updateContactAnchors add the time they take (detection and response, steady_clock) to a total kept in data's
/// scratch, which contactSeconds reads. Off by default (then nothing is timed); a
/// counter, not state: it changes no result. Nothing without CONTACT.
void setContactTiming(const Data& data, bool on);
/// The total of setContactTiming [s] since it was switched on (0 without CONTACT).
double contactSeconds(const Data& data);
/// How many times data's scratch has searched for the pairs that may touch (the broad
/// phase: on the first evaluation and whenever a moving solid's bounding box has left
/// its margin, docs/contact.md); a counter, not state. 0 without CONTACT.
long contactPairSearches(const Data& data);

}  // namespace solver
