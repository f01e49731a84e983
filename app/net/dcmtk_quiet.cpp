#include "net/dcmtk_quiet.hpp"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/oflog/oflog.h>

namespace steerseg::net {

void quietDcmtk() {
    OFLog::getLogger("dcmtk").setLogLevel(OFLogger::FATAL_LOG_LEVEL);
}

} // namespace steerseg::net
