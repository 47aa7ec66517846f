// `illum history`'s sheet, which the library's history() returns too.
#pragma once

#include <illum/sheet.h>

#include "scene_options.h"

namespace illum::cli {

// The sheet of the scene the options make as each model from Wylie (1967) to Kajiya (1986) drew it.
// Model files are read through `models` (when given) as prepareScene reads them.
Sheet historySheet(const SceneOptions& o, ModelCache* models = nullptr);

}  // namespace illum::cli
