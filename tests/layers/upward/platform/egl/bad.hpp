#pragma once
// Deliberately against the rule: platform code must not see the session.
#include "session/session.hpp"
