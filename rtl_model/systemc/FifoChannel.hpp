// The clocked FIFO as a SystemC primitive channel: stages reach it through
// ports of its two interfaces; reads and writes take effect in the update
// phase of the clock edge's delta cycle, like registers, through the same
// core (stage::ClockedFifo) the fast model uses. Final: a stage module whose
// port is bound to one calls it directly (StageModule), not through the
// interface's virtual functions.
#pragma once
#include <systemc>

#include <string>

#include "rtl_model/stages/ClockedFifo.hpp"

namespace arp::scm {

template <class T>
class FifoWriteIf : virtual public sc_core::sc_interface {
 public:
  virtual bool can_write() const = 0;
  virtual void write(const T& v, int64_t cycle) = 0;
  virtual T& emplace(int64_t cycle) = 0;
  virtual void note_blocked() = 0;
};

template <class T>
class FifoReadIf : virtual public sc_core::sc_interface {
 public:
  virtual bool can_read() const = 0;
  virtual const T& front() const = 0;
  virtual void read(int64_t cycle) = 0;
};

template <class T>
class FifoChannel final : public sc_core::sc_prim_channel, public FifoWriteIf<T>, public FifoReadIf<T> {
 public:
  FifoChannel(const char* name, int depth) : sc_core::sc_prim_channel(name), core_(name, depth) {}

  ARP_FIFO_OP bool can_write() const override { return core_.can_write(); }
  ARP_FIFO_OP void write(const T& v, int64_t cycle) override {
    core_.write(v, cycle);
    request_update();
  }
  ARP_FIFO_OP T& emplace(int64_t cycle) override {
    request_update();
    return core_.emplace(cycle);
  }
  void note_blocked() override { core_.note_blocked(); }
  ARP_FIFO_OP bool can_read() const override { return core_.can_read(); }
  ARP_FIFO_OP const T& front() const override { return core_.front(); }
  ARP_FIFO_OP void read(int64_t cycle) override {
    core_.read(cycle);
    request_update();
  }

  stage::ClockedFifo<T>& core() { return core_; }
  const stage::ClockedFifo<T>& core() const { return core_; }

 protected:
  void update() override { core_.update(); }

 private:
  stage::ClockedFifo<T> core_;
};

}  // namespace arp::scm
