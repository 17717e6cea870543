#pragma once
// Convenience header: every input reader.
#include "core/io/dataset.h"
#include "core/io/depth_png.h"
#include "core/io/frame_source.h"
#include "core/io/organized_pcd.h"
#include "core/io/read_options.h"
