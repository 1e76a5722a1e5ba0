#include "Workers.h"

namespace aeronc::recognition {
namespace {
thread_local int slot = 0;
}  // namespace

int workerSlot() { return slot; }
void setWorkerSlot(int s) { slot = s; }

}  // namespace aeronc::recognition
