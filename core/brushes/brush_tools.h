// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file brush_tools.h
/// @brief The tools behind applyStamp (brush.h), one file each; see brush.h for what each does.
///        All take validated settings, work on a LocalPatch, and mark and return the leaves
///        they changed.

#include "core/brushes/brush.h"
#include "core/local/sphere_stamp.h"

namespace sculpt {

/// add_carve.cpp: union (Add) or difference (Carve) of a ball swept from the previous stamp.
DirtyRegion sweepBall(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, CsgMode mode,
                      LeafJournal* journal);
/// inflate.cpp: direction +1 inflates, -1 deflates.
DirtyRegion inflate(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, double direction,
                    LeafJournal* journal);
/// smooth.cpp
DirtyRegion smoothUnder(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
/// flatten.cpp
DirtyRegion flatten(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
/// grab.cpp
DirtyRegion grab(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
/// pinch.cpp
DirtyRegion pinch(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
/// follow.cpp
DirtyRegion follow(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
/// primitive_stamp.cpp
DirtyRegion stampPrimitives(FieldImage& field, const PrimitiveStamp& primitive, const BrushStamp& stamp,
                            LeafJournal* journal);

}  // namespace sculpt
