#pragma once
// Which worker the calling thread is while a setup's levels are sliced: 0 for the thread
// that called recognise(), 1, 2, ... for the helpers. The caches that threads cannot share
// (OCCT classifiers and ray intersectors keep cursors) are kept per worker, so they are built
// once per worker, not once per thread started.
namespace aeronc::recognition {

int workerSlot();
void setWorkerSlot(int slot);

}  // namespace aeronc::recognition
