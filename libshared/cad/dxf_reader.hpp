/// @file dxf_reader.hpp
/// @brief Reads a DXF file (ASCII R12 to R2018, or binary DXF) into a
/// Drawing: LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE/VERTEX (2D), ELLIPSE and
/// SPLINE (the last two flattened within a chord tolerance) from the
/// ENTITIES section, in world XY coordinates. Other entities are counted,
/// never silently dropped.
///
/// What is read:
/// - HEADER: $ACADVER (Drawing::version) and $INSUNITS (Drawing::insunits).
///   Other sections (TABLES, BLOCKS, OBJECTS, ...) are passed over, and so
///   are tags between sections and a stray ENDSEC.
/// - ENTITIES, in model space. Entities with group code 67 = 1 (paper
///   space) are skipped as "TYPE (paper space)". LINE and ELLIPSE are in
///   world coordinates and SPLINE control points too (z is dropped); ARC,
///   CIRCLE, LWPOLYLINE and POLYLINE are in the entity's OCS: extrusion
///   (0,0,1) is taken as it is, (0,0,-1) mirrors x (x -> -x, and arcs and
///   bulges turn the other way), any other extrusion skips the entity as
///   "TYPE (not in XY plane)". An ELLIPSE with extrusion (0,0,-1) keeps its
///   points but runs clockwise.
/// - ARC angles follow ezdxf: equal start and end angles make no arc,
///   angles equal modulo 360 a full circle. Arcs over 180 degrees and
///   circles become two arcs, so that no bulge exceeds 1.
/// - LWPOLYLINE vertices are taken as they come (group code 90 is not
///   trusted); POLYLINE takes its VERTEX entities up to SEQEND (or the next
///   entity), leaving out spline frame control points (vertex flag 16). 3D
///   polylines, polygon and polyface meshes (flags 8, 16, 64) are skipped as
///   "POLYLINE (3D)", "POLYLINE (polygon mesh)", "POLYLINE (polyface mesh)".
///   The ATTRIBs and SEQEND of an INSERT belong to the INSERT (skipped).
/// - SPLINE: NURBS by de Boor, flattened within chord_tolerance (at most
///   100,000 points a curve, degree at most 10); a SPLINE with only fit
///   points is the polyline through them. An inconsistent definition is
///   skipped as "SPLINE (invalid)", one with more than 100,000 control
///   points as "SPLINE (too large)".
/// - Segment::entity counts every entity of the section (a POLYLINE with its
///   VERTEX and SEQEND is one); Segment::source_line is the line of the
///   entity's "0"; zero-length pieces are left out (their entity is still
///   counted as read). Drawing::layers holds the layers of the entities
///   read, in order of first use ("0" when an entity names none).
///
/// Errors (tk::Error, "name:LINE: message" at the line at fault, or
/// "name: byte OFFSET: message" in binary DXF): a bad group code, a code
/// without a value, a bad or non-finite number ("bad number 'x' for group
/// code 10", "number out of range ..."), a NUL byte in ASCII DXF, a
/// truncated binary value, coordinates that overflow, more than
/// max_segments segments, an ENTITIES section cut off by the end of the file,
/// and a file without an ENTITIES section ("no ENTITIES section", which is
/// what an empty file gives). A missing EOF is fine.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "cad/drawing.hpp"

namespace tk::cad {

struct DxfReadOptions {
  double chord_tolerance = 0.001;       ///< drawing units, for ELLIPSE and SPLINE
  std::size_t max_segments = 20000000;  ///< a bound on memory for hostile files
};

/// Parses a whole file held in memory; `name` names it in errors
/// ("name:line: message", the line of the group code at fault).
Drawing read_dxf(std::string_view contents, const std::string& name, const DxfReadOptions& options = {});

/// Reads `path` ("-" is stdin) and parses it.
Drawing read_dxf_file(const std::string& path, const DxfReadOptions& options = {});

}  // namespace tk::cad
