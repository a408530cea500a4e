#pragma once
/// @file brush_tools.h
/// @brief The tools behind applyStamp (brush.h), one function each; see brush.h for what each
///        does. All take validated settings and mark and return the leaves they changed.

#include "brush.h"
#include "sphere_stamp.h"

namespace sculpt {

DirtyRegion sweepBall(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, CsgMode mode,
                      LeafJournal* journal);
/// direction +1 inflates, -1 deflates.
DirtyRegion inflate(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, double direction,
                    LeafJournal* journal);
DirtyRegion smoothUnder(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
DirtyRegion flatten(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
DirtyRegion grab(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
DirtyRegion pinch(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal);
DirtyRegion stampPrimitives(FieldImage& field, const PrimitiveStamp& primitive, const BrushStamp& stamp,
                            LeafJournal* journal);

} // namespace sculpt
