// mocapfill's public C++ API: everything a program needs to read, convert, retarget,
// filter and fill motion. Link mocapfill::mocapfill (find_package(mocapfill CONFIG)).
#pragma once

#include "mocapfill/database.h"
#include "mocapfill/error.h"
#include "mocapfill/fill.h"
#include "mocapfill/filter.h"
#include "mocapfill/io.h"
#include "mocapfill/pca.h"
#include "mocapfill/pipeline.h"
#include "mocapfill/retarget.h"
#include "mocapfill/scene.h"
#include "mocapfill/version.h"
