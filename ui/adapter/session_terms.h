// The render session's terms as the rest of the designer names them: the interaction policy
// (its fields, parameter descriptors and JSON) that Preferences edits and stores, the
// governor's levels the status bar names, and the pass reports the controller's signals
// carry. render/session/ is the adapter's to include; this header is the other rooms' one
// door to the session's vocabulary, so a change there is met here.
#pragma once

#include "session/governor.h"
#include "session/interaction_policy.h"
#include "session/session_observer.h"
