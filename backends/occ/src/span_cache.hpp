// Per-thread evaluators that keep OCC's span cache of a B-spline or Bezier surface.
//
// Geom_BSplineSurface::D2 locates the parameter's span and runs Bohm's scheme over the span's
// poles on every call. GeomAdaptor_Surface keeps the span's polynomial (BSplSLib_Cache) and
// evaluates only that while queries stay in the span, which marching, Newton and sampling queries
// mostly do: several times fewer operations per query. The cache is mutable, so one adaptor may
// serve one thread only: each thread keeps its own per surface, found by the surface's serial.
#pragma once

#include <GeomAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>

#include <cstdint>

namespace semimesh::occ {

/// A serial number no other surface of this process has (keys the per-thread adaptors, so a new
/// surface at the address of a destroyed one never meets its stale adaptor).
std::uint64_t new_surface_serial();

/// The calling thread's adaptor of `surface`, which has serial `serial` (built on first use).
/// Valid until the thread's next call.
const GeomAdaptor_Surface& thread_adaptor(std::uint64_t serial, const Handle(Geom_Surface)& surface);

/// The calling thread's own copy of `surface` (Geom_Surface::Copy: the same geometry, evaluated by
/// the same code, so to the same bits), which has serial `serial` (built on first use): for a
/// surface OCC evaluates through an evaluator it may cache in (revolution, extrusion, offset), so
/// that threads never share one. Valid until the thread's next call.
const Handle(Geom_Surface)& thread_copy(std::uint64_t serial, const Handle(Geom_Surface)& surface);

}  // namespace semimesh::occ
