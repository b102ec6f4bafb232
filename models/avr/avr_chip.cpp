#include "avr/avr_chip.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "avr/atmega328p_regs.hpp"
#include "avr/core/elf_check.hpp"
#include "avr/core/intel_hex.hpp"
#include "avr/core/vector_table.hpp"
#include "common/bad_input.hpp"

#include <avr_eeprom.h>
#include <avr_extint.h>
#include <avr_ioport.h>
#include <avr_timer.h>
#include <avr_uart.h>
#include <sim_avr.h>
#include <sim_core.h>
#include <sim_cycle_timers.h>
#include <sim_elf.h>
#include <sim_interrupts.h>
#include <sim_io.h>
#include <sim_regbit.h>

namespace cnc::avr {

namespace {

void quiet_logger(avr_t*, const int level, const char* format, va_list ap) {
    if (level <= LOG_ERROR) std::vfprintf(stderr, format, ap);  // errors only, and to stderr: stdout is cncsim's
}

constexpr avr_cycle_count_t kInterruptResponseCycles = 4;
// Datasheet "Interrupt Response Time": an interrupt that wakes the MCU from sleep takes 4 cycles more, in addition to
// the sleep mode's start-up time (0 in Idle, whose clocks run on: "Sleep Modes").
constexpr avr_cycle_count_t kWakeUpCycles = 4;

// The image libsimavr's loader allocates (malloc), freed whatever check refuses it.
struct LoadedFirmware {
    elf_firmware_t fw{};
    LoadedFirmware() { std::memset(&fw, 0, sizeof fw); }
    ~LoadedFirmware() {
        std::free(fw.flash);
        std::free(fw.eeprom);
    }
    LoadedFirmware(const LoadedFirmware&) = delete;
    LoadedFirmware& operator=(const LoadedFirmware&) = delete;
};

void no_sleep(avr_t*, avr_cycle_count_t) {}  // simavr's default usleep()s to follow the wall clock

avr_cycle_count_t no_op_timer(avr_t*, avr_cycle_count_t, void*) {
    return 0;
}

}  // namespace

struct AvrChip::PortHooks {
    std::array<avr_io_write_t, 12> write{};
    std::array<void*, 12> write_param{};  // PINx, DDRx, PORTx of up to 4 ports, in McuMap::ports order
    std::array<avr_io_read_t, 12> read{};
    std::array<void*, 12> read_param{};
};

struct AvrChip::Bridge {
    static void write(avr_t*, avr_io_addr_t addr, std::uint8_t v, void* chip) {
        static_cast<AvrChip*>(chip)->io_write(addr, v);
    }
    static std::uint8_t read(avr_t*, avr_io_addr_t addr, void* chip) {
        return static_cast<AvrChip*>(chip)->io_read(addr);
    }
    static avr_cycle_count_t scheduler(avr_t* avr, avr_cycle_count_t, void* chip) {
        auto* self = static_cast<AvrChip*>(chip);
        const auto next = self->process_events(static_cast<Cycle>(avr->cycle));
        self->m_scheduled = next;  // simavr inserts the timer again at the cycle returned (sim_cycle_timers.c)
        return next ? static_cast<avr_cycle_count_t>(*next) : 0;
    }
    static void pending(avr_irq_t* irq, std::uint32_t value, void* chip) {
        if (value != 0) return;
        auto* self = static_cast<AvrChip*>(chip);
        self->vector_cleared(self->m_vectors.at(irq->irq / 256));  // sim_interrupts.c: irq base = vector * 256
    }
    static void running(avr_irq_t* irq, std::uint32_t value, void* chip) {
        auto* self = static_cast<AvrChip*>(chip);
        if (value == 0) {
            self->m_reti_ran = true;  // sim_interrupts.c avr_interrupt_reti: the vector stops running at its RETI
            return;
        }
        self->vector_entered(self->m_vectors.at(irq->irq / 256));
    }
};

AvrChip::AvrChip(const AvrCoreConfig& cfg)
    : m_map(checked_mcu(cfg)),
      m_f_cpu_hz(cfg.f_cpu_hz),
      m_clock(cfg.f_cpu_hz == 0 ? 1 : cfg.f_cpu_hz, cfg.clock, "clock"),
      m_usart(static_cast<UsartSink&>(*this), cfg.keep_usart_logs),
      m_port_hooks(std::make_unique<PortHooks>()) {
    if (cfg.f_cpu_hz == 0) throw BadInput(cfg.where, "the AVR clock frequency must be above 0 Hz");
    validate(cfg.pins, cfg.where, m_map.mcu);

    avr_global_logger_set(quiet_logger);
    LoadedFirmware loaded;
    elf_firmware_t& fw = loaded.fw;
    if (is_intel_hex(cfg.firmware_elf)) {
        // A HEX image says nothing of its clock (the configuration's) and of its MCU but by its vector table.
        std::vector<std::uint8_t> image = load_intel_hex(cfg.firmware_elf, m_map.flash_bytes, cfg.where);
        check_vector_table(image, m_map.mcu, cfg.firmware_elf, cfg.where, cfg.mcu_key);
        fw.flash = static_cast<std::uint8_t*>(std::malloc(image.size()));
        std::memcpy(fw.flash, image.data(), image.size());
        fw.flashsize = static_cast<std::uint32_t>(image.size());
    } else {
        const ElfInfo info = check_avr_elf(cfg.firmware_elf, cfg.mcu, cfg.f_cpu_hz, cfg.where, cfg.mcu_key);
        if (elf_read_firmware(cfg.firmware_elf.c_str(), &fw) != 0)
            throw BadInput(cfg.where, "libsimavr could not load the firmware ELF '" + cfg.firmware_elf + "'");
        if (fw.flashsize > m_map.flash_bytes)
            throw BadInput(cfg.where, "firmware '" + cfg.firmware_elf + "' has " + std::to_string(fw.flashsize) +
                                          " bytes of flash, the " + m_map.display + " " +
                                          std::to_string(m_map.flash_bytes));
        if (info.mmcu.empty())
            check_vector_table(std::vector<std::uint8_t>(fw.flash, fw.flash + fw.flashsize), m_map.mcu,
                               cfg.firmware_elf, cfg.where, cfg.mcu_key);
    }
    m_avr = avr_make_mcu_by_name(cfg.mcu.c_str());
    if (m_avr == nullptr) throw BadInput(cfg.where, "libsimavr has no MCU '" + cfg.mcu + "'");
    avr_init(m_avr);
    fw.frequency = cfg.f_cpu_hz;
    avr_load_firmware(m_avr, &fw);
    m_avr->frequency = cfg.f_cpu_hz;
    m_avr->sleep = no_sleep;
    std::uint32_t flags = 0;  // not the default POLL_SLEEP|STDIO (simavr's UART is bypassed, but keep it quiet)
    avr_ioctl(m_avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);

    TimerSink& sink = *this;
    m_timers[0] = std::make_unique<TimerUnit>(kTimer0, m_prescaler01, sink);
    m_timers[1] = std::make_unique<TimerUnit>(kTimer1, m_prescaler01, sink);
    m_timers[2] = std::make_unique<TimerUnit>(kTimer2, m_prescaler2, sink);
    for (std::size_t i = 0; i < kPinSignals.size(); ++i) m_line_sources[i] = pin_source(cfg.pins.at(kPinSignals[i]));
    install_hooks();
    if (cfg.fast_forward)
        // PINx reads the pins (inputs change only between run_until calls), UCSRnA the USART's flags (they change
        // only at its events); both without side effects.
        m_skipper = std::make_unique<LoopSkipper>(m_avr, pin_registers(), std::vector<std::uint16_t>{m_map.usart.ucsra},
                                                  [this] { return quiet_until(); });
    m_initial[kTxdLine] = true;  // the USART line idles high
    m_level = m_initial;
}

const McuMap& AvrChip::checked_mcu(const AvrCoreConfig& cfg) {
    const auto mcu = mcu_by_name(cfg.mcu);
    if (!mcu) throw BadInput(cfg.where, "MCU '" + cfg.mcu + "' is not modelled (modelled: " + modelled_mcus() + ")");
    return mcu_map(*mcu);
}

AvrChip::~AvrChip() {
    if (m_avr == nullptr) return;
    avr_terminate(m_avr);
    std::free(m_avr);
}

void AvrChip::install_hooks() {
    avr_t* avr = m_avr;
    for (int i = 0; i < avr->interrupts.vector_count; ++i) {
        avr_int_vector_t* v = avr->interrupts.vector[i];
        if (v->vector < m_vectors.size()) m_vectors[v->vector] = v;
    }
    for (const auto& timer : m_map.vector) {
        for (const int n : timer) {
            if (n != 0 && m_vectors[static_cast<std::size_t>(n)] == nullptr)
                throw std::runtime_error(std::string("libsimavr's ") + m_map.name + " lacks interrupt vector " +
                                         std::to_string(n));
        }
    }
    // RXC and UDRE stay set while their condition holds (sticky); they are re-raised after their vector runs.
    for (const int n : {m_map.usart.vector_rxc, m_map.usart.vector_udre}) {
        avr_int_vector_t* v = m_vectors[static_cast<std::size_t>(n)];
        v->raise_sticky = 1;
        avr_irq_register_notify(v->irq + AVR_INT_IRQ_PENDING, Bridge::pending, this);
    }
    for (avr_int_vector_t* v : m_vectors) {
        if (v != nullptr) avr_irq_register_notify(v->irq + AVR_INT_IRQ_RUNNING, Bridge::running, this);
    }

    // simavr's Timer1 connects ICP1 (PB0 on the ATmega328P, PD6 on the ATmega16) to its input capture; capture
    // is not modelled here, and simavr's version would capture a TCNT1 of 0 from its idle timer on every edge.
    const bool m16 = m_map.mcu == Mcu::Atmega16;
    avr_irq_t* icp_pin =
        avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(m16 ? 'D' : 'B'), m16 ? IOPORT_IRQ_PIN6 : IOPORT_IRQ_PIN0);
    avr_irq_t* icp_in = avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('1'), TIMER_IRQ_IN_ICP);
    if (icp_pin != nullptr && icp_in != nullptr) avr_unconnect_irq(icp_pin, icp_in);
    if (!m16) disconnect_external_interrupts();

    const auto take_write = [&](std::uint16_t addr) {
        auto& io = avr->io[AVR_DATA_TO_IO(addr)];
        io.w.c = Bridge::write;
        io.w.param = this;
    };
    const auto take_read = [&](std::uint16_t addr) {
        auto& io = avr->io[AVR_DATA_TO_IO(addr)];
        io.r.c = Bridge::read;
        io.r.param = this;
    };
    for (std::size_t p = 0; p < m_map.ports.size(); ++p) {
        for (std::uint16_t r = 0; r < 3; ++r) {
            const std::uint16_t a = m_map.ports[p].pin + r;
            const std::size_t i = 3 * p + r;
            auto& io = avr->io[AVR_DATA_TO_IO(a)];
            m_port_hooks->write[i] = io.w.c;
            m_port_hooks->write_param[i] = io.w.param;
            m_port_hooks->read[i] = io.r.c;
            m_port_hooks->read_param[i] = io.r.param;
            take_write(a);
            if (r == 0) take_read(a);  // PINx
        }
    }
    const UsartRegs& u = m_map.usart;
    for (const std::uint16_t a : {u.udr, u.ucsra, u.ucsrb, u.ucsrc, u.ubrrl, u.ubrrh}) take_write(a);
    // Registers whose value is computed when read: UCSRnA, UDRn, and the ATmega16's UBRRH/UCSRC pair.
    for (const std::uint16_t a : {u.ucsra, u.udr}) take_read(a);
    if (u.shared_ucsrc()) take_read(u.ucsrc);
    // Datasheet §20.11 / doc2466 reset values (simavr's UART reset sets TXEN "to allow printf").
    avr->data[u.ucsra] = m_usart.ucsra();
    avr->data[u.ucsrb] = m_usart.ucsrb();
    if (!u.shared_ucsrc()) avr->data[u.ucsrc] = m_usart.ucsrc();
    if (m16) {
        install_atmega16_hooks(take_write, take_read);
        return;
    }
    using namespace reg;
    for (const std::uint16_t a :
         {kTifr0,  kTifr1,  kTifr2,  kGtccr,  kTccr0a, kTccr0b, kTcnt0,  kOcr0a, kOcr0b, kTimsk0,
          kTimsk1, kTimsk2, kTccr1a, kTccr1b, kTccr1c, kTcnt1l, kTcnt1h, kIcr1l, kIcr1h, kOcr1al,
          kOcr1ah, kOcr1bl, kOcr1bh, kTccr2a, kTccr2b, kTcnt2,  kOcr2a,  kOcr2b, kAssr})
        take_write(a);
    // Registers whose value is computed when read: TCNTn, Timer1's TEMP pairs.
    for (const std::uint16_t a : {kTcnt0, kTcnt1l, kTcnt1h, kIcr1l, kIcr1h, kTcnt2}) take_read(a);
}

void AvrChip::disconnect_external_interrupts() {
    // simavr 1.6's INT0/INT1 (avr_extint.c) follow PD2/PD3, and in the reset low-level mode (EICRA ISCn1:0 = 00)
    // poll a low pin with a cycle timer at every cycle, whatever EIMSK says, setting INTFn, which the datasheet
    // keeps clear in that mode ("EIFR"). grbl's STEP_X/STEP_Y are PD2/PD3 and low between pulses, so that poll was
    // most of grbl's simulation time. No input but RXD reaches the ATmega328P's pins, so INT0/INT1 are left out.
    for (int n = 0; n < 2; ++n) {
        avr_irq_t* pin = avr_io_getirq(m_avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_PIN2 + n);
        avr_irq_t* detector = avr_io_getirq(m_avr, AVR_IOCTL_EXTINT_GETIRQ(), EXTINT_IRQ_OUT_INT0 + n);
        if (pin != nullptr && detector != nullptr) avr_unconnect_irq(pin, detector);
    }
}

std::vector<std::uint16_t> AvrChip::pin_registers() const {
    std::vector<std::uint16_t> pins;
    for (const auto& port : m_map.ports) pins.push_back(port.pin);
    return pins;
}

// The first cycle timer other than the scheduler's (simavr's peripherals and the run_until boundary), or none.
const avr_cycle_timer_slot_t* AvrChip::other_cycle_timer() const {
    const avr_cycle_timer_slot_t* t = m_avr->cycle_timers.timer;  // sorted by cycle
    while (t != nullptr && t->timer == Bridge::scheduler) t = t->next;
    return t;
}

// Instructions until the cycle count reaches `limit` or the CPU stops, each as libsimavr 1.6's avr_callback_run_raw
// (sim_avr.c) runs one, but without visiting the cycle timers when none is due and the CPU runs on: that visit cost
// as much as the instruction. One loop, not a call per instruction: the call cost a tenth of the time on grbl.
void AvrChip::run_instructions(Cycle limit) {
    avr_t* avr = m_avr;
    LoopSkipper* skipper = m_skipper.get();
    while (static_cast<Cycle>(avr->cycle) < limit) {
        const avr_flashaddr_t pc = avr->pc;
        avr_flashaddr_t new_pc = pc;
        if (avr->state == cpu_Running) {
            if (skipper != nullptr && skipper->recording()) skipper->before_instruction();
            new_pc = avr_run_one(avr);
        }
        const avr_cycle_timer_slot_t* head = avr->cycle_timers.timer;
        avr_cycle_count_t sleep = 0;
        if (avr->state != cpu_Running || (head != nullptr && head->when <= avr->cycle)) {
            // The scheduler's events say themselves whether the CPU can see them (timer_flag, timer_output, usart_*);
            // the run_until boundary changes nothing.
            if (skipper != nullptr && other_timer_due()) skipper->disturb();
            sleep = avr_cycle_timer_process(avr);
        }
        avr->pc = new_pc;
        if (avr->state == cpu_Sleeping) {
            if (avr->sreg[S_I] == 0) {
                avr->state = cpu_Done;
                return;
            }
            avr->sleep(avr, sleep);
            avr->cycle += 1 + sleep;
        }
        if ((avr->state == cpu_Running || avr->state == cpu_Sleeping) && avr->interrupt_state != 0)
            avr_service_interrupts(avr);
        if (avr->state == cpu_Done || avr->state == cpu_Crashed || avr->state == cpu_Stopped) return;
        const bool reti = m_reti_ran;
        m_reti_ran = false;
        if (skipper == nullptr || avr->state != cpu_Running) continue;
        // After RETI one more instruction runs before any interrupt (interrupt_state -2, -1, then 0 or pending).
        if (reti) {
            m_after_reti = true;
        } else if (m_after_reti && avr->interrupt_state >= 0) {
            m_after_reti = false;
            if (avr->interrupt_state == 0 && skipper->resume_on_proof()) continue;
        }
        if (avr->pc <= pc) skipper->backward_jump();  // an iteration may end here
    }
}

bool AvrChip::other_timer_due() const {
    for (const avr_cycle_timer_slot_t* t = m_avr->cycle_timers.timer; t != nullptr && t->when <= m_avr->cycle;
         t = t->next) {
        if (t->timer != Bridge::scheduler && t->timer != no_op_timer) return true;
    }
    return false;
}

namespace {

// What a timer's coming events would do: whether any is seen by the CPU.
class EventProbe final : public TimerSink {
public:
    EventProbe(std::function<bool(char, TimerFlag)> quiet, bool outputs_seen)
        : m_quiet(std::move(quiet)), m_outputs_seen(outputs_seen) {}
    void timer_flag(char timer, TimerFlag flag, Cycle) override { m_seen = m_seen || !m_quiet(timer, flag); }
    void timer_output(char, Cycle) override { m_seen = m_seen || m_outputs_seen; }
    [[nodiscard]] bool seen() const { return m_seen; }

private:
    std::function<bool(char, TimerFlag)> m_quiet;
    bool m_outputs_seen;  // through PINx
    bool m_seen = false;
};

}  // namespace

bool AvrChip::quiet_flag(char timer, TimerFlag flag) const {
    // Raising a flag that is already set, with its interrupt disabled, changes nothing.
    const int n = timer_vector(timer - '0', flag);
    if (n == 0) return true;
    const avr_int_vector_t* v = m_vectors.at(static_cast<std::size_t>(n));
    return avr_regbit_get(m_avr, v->raised) != 0 && avr_regbit_get(m_avr, v->enable) == 0;
}

Cycle AvrChip::quiet_until() const {
    // The run_until boundary's own cycle timer is gone once it has fired, in the step that reached it.
    Cycle until = m_run_limit;
    if (const avr_cycle_timer_slot_t* t = other_cycle_timer()) until = std::min(until, static_cast<Cycle>(t->when));
    if (const auto u = m_usart.next_event()) until = std::min(until, *u);
    for (const auto& timer : m_timers) {
        if (const auto e = timer->next_event(); !e || *e >= until) continue;
        EventProbe probe([this](char t, TimerFlag f) { return quiet_flag(t, f); }, m_skipper->pins_read());
        TimerUnit ahead = timer->copy_for(probe);  // from its last processed event: one due now counts too
        for (auto e = ahead.next_event(); e && *e < until; e = ahead.next_event()) {
            ahead.advance_to(*e);
            if (probe.seen()) until = *e;
        }
    }
    return until;
}

Cycle AvrChip::now() const {
    return static_cast<Cycle>(m_avr->cycle);
}
Cycle AvrChip::cycle() const {
    return now();
}

ChipState AvrChip::run_until(Cycle limit) {
    if (m_state == ChipState::Running && limit > now()) {
        // Bounds a sleep: a sleeping simavr core jumps straight to its next cycle timer.
        avr_cycle_timer_register(m_avr, static_cast<avr_cycle_count_t>(limit - now()), no_op_timer, this);
        m_run_limit = limit;
        if (m_skipper && m_avr->state == cpu_Running && m_avr->interrupt_state == 0) m_skipper->resume_on_proof();
        run_instructions(limit);
        const int st = m_avr->state;
        if (st == cpu_Done || st == cpu_Crashed || st == cpu_Stopped) {
            m_state = st == cpu_Done ? ChipState::Done : ChipState::Crashed;
            m_stop_cycle = now();
            if (m_state == ChipState::Crashed)
                std::fprintf(stderr, "avr: the firmware crashed at cycle %lld (pc 0x%x)\n",
                             static_cast<long long>(now()), static_cast<unsigned>(m_avr->pc));
        }
        avr_cycle_timer_cancel(m_avr, no_op_timer, this);
    }
    if (m_state != ChipState::Running && limit > now()) {
        // The CPU has stopped (cli; sleep) but the timers and the USART run on, as on silicon: jump to `limit`
        // and let the cycle timers catch up (each is called with its exact cycle).
        m_avr->cycle = static_cast<avr_cycle_count_t>(limit);
        avr_cycle_timer_process(m_avr);
    }
    return m_state;
}

std::vector<std::uint8_t> AvrChip::eeprom() const {
    std::vector<std::uint8_t> out(m_avr->e2end + 1);
    avr_eeprom_desc_t d;
    std::memset(&d, 0, sizeof d);
    d.ee = out.data();
    d.size = static_cast<std::uint32_t>(out.size());
    // simavr 1.6's EEPROM GET copies the bytes but returns -1 (its `res` is never set on that path): not checked.
    (void)avr_ioctl(m_avr, AVR_IOCTL_EEPROM_GET, &d);
    return out;
}

std::size_t AvrChip::port_index(char port) const {
    for (std::size_t i = 0; i < m_map.ports.size(); ++i) {
        if (m_map.ports[i].port == port) return i;
    }
    throw std::out_of_range(std::string("no port ") + port + " on the " + m_map.name);
}

void AvrChip::drive_input(const Pin& pin, bool level) {
    std::int8_t& driven = m_inputs.at(port_index(pin.port)).at(static_cast<std::size_t>(pin.bit));
    const bool was = driven < 0 ? pin_level(pin) : driven != 0;
    driven = level ? 1 : 0;
    disturb();
    if (m_map.mcu == Mcu::Atmega16) external_interrupt_edge(pin, was, level);
}

std::vector<LineEvent> AvrChip::take_events(Cycle upto) {
    std::stable_sort(m_events.begin(), m_events.end(),
                     [](const LineEvent& a, const LineEvent& b) { return a.cycle < b.cycle; });
    const auto split =
        std::find_if(m_events.begin(), m_events.end(), [upto](const LineEvent& e) { return e.cycle > upto; });
    std::vector<LineEvent> out(m_events.begin(), split);
    m_events.erase(m_events.begin(), split);
    return out;
}

void AvrChip::deliver_rx(Cycle start, Cycle decision, const uart::RxFrame& frame) {
    m_usart.receive(start, decision, frame);
    disturb();
    reschedule();
}

// ---- scheduler ----

std::optional<Cycle> AvrChip::next_event() const {
    std::optional<Cycle> best = m_usart.next_event();
    for (const auto& t : m_timers) {
        const auto e = t->next_event();
        if (e && (!best || *e < *best)) best = e;
    }
    return best;
}

std::optional<Cycle> AvrChip::process_events(Cycle c) {
    m_in_scheduler = true;
    for (auto t = next_event(); t && *t <= c; t = next_event()) {
        for (auto& timer : m_timers) timer->advance_to(*t);
        m_usart.advance_to(*t);
    }
    m_in_scheduler = false;
    if (m_quiet_flags_stale) update_quiet_flags();
    return next_event();
}

// Called wherever a timer flag or its enable bit may have changed: after the scheduler's events raised a flag, and
// after a write to TIFRn or TIMSKn (reschedule). Taking a vector clears an enabled flag: not quiet before or after.
void AvrChip::update_quiet_flags() {
    m_quiet_flags_stale = false;
    const Cycle c = now();
    for (auto& timer : m_timers) {
        std::uint8_t mask = 0;
        for (const TimerFlag f : {TimerFlag::Overflow, TimerFlag::CompareA, TimerFlag::CompareB, TimerFlag::Capture})
            if (quiet_flag(timer->spec().name, f))
                mask = static_cast<std::uint8_t>(mask | (1U << static_cast<unsigned>(f)));
        timer->set_quiet_flags(c, mask);
    }
}

void AvrChip::reschedule() {
    if (m_in_scheduler) return;  // the scheduler returns its next time to simavr itself
    if (m_quiet_flags_stale) update_quiet_flags();
    std::optional<Cycle> next = next_event();
    if (next) next = std::max(*next, now());
    if (next == m_scheduled) return;
    m_scheduled = next;
    if (!next) {
        avr_cycle_timer_cancel(m_avr, Bridge::scheduler, this);
        return;
    }
    avr_cycle_timer_register(m_avr, static_cast<avr_cycle_count_t>(*next - now()), Bridge::scheduler, this);
}

// ---- interrupts ----

void AvrChip::raise(int vector_number, Cycle c) {
    raise_vector(m_vectors.at(static_cast<std::size_t>(vector_number)), c);
}

void AvrChip::raise_vector(avr_int_vector_t* v, Cycle c) {
    const bool sleeping = m_avr->state == cpu_Sleeping;
    avr_raise_interrupt(m_avr, v);  // wakes a sleeping CPU when the interrupt is enabled
    if (sleeping && m_avr->state == cpu_Running && !m_wake_flag_cycle) m_wake_flag_cycle = c;
}

void AvrChip::sync_level_vector(int vector_number, bool flag, Cycle c) {
    avr_int_vector_t* v = m_vectors.at(static_cast<std::size_t>(vector_number));
    if (flag) {
        if (v->pending == 0) raise_vector(v, c);
        return;
    }
    if (v->pending != 0) avr_clear_interrupt(m_avr, v);
    avr_regbit_clear(m_avr, v->raised);
}

void AvrChip::vector_cleared(avr_int_vector_t* v) {
    // A level interrupt whose vector was just taken (or cleared) fires again while its condition holds.
    const bool holds = v->vector == m_map.usart.vector_rxc ? m_usart.rxc() : m_usart.udre();
    if (holds && avr_regbit_get(m_avr, v->enable) != 0) avr_raise_interrupt(m_avr, v);
}

void AvrChip::vector_entered(avr_int_vector_t* v) {
    disturb();
    if (m_map.mcu == Mcu::Atmega16) external_interrupt_entered(v->vector);
    // Datasheet "Interrupt Response Time": pushing the return address takes at least 4 cycles before the vector
    // runs; libsimavr 1.6's avr_service_interrupts drops that count, which put every edge an ISR
    // writes 4 cycles early. Woken from sleep, the vector runs 4 + 4 cycles after the flag that woke the CPU
    // (libsimavr's sleeping core reaches the flag's cycle, or one past it, and charges nothing).
    if (m_wake_flag_cycle) {
        m_avr->cycle = std::max(m_avr->cycle, static_cast<avr_cycle_count_t>(*m_wake_flag_cycle) +
                                                  kInterruptResponseCycles + kWakeUpCycles);
        m_wake_flag_cycle.reset();
    } else {
        m_avr->cycle += kInterruptResponseCycles;
    }
    if (v->vector == m_map.usart.vector_txc) m_usart.clear_txc(now());  // §20.6.3: TXC clears when its vector runs
}

void AvrChip::usart_flags(Cycle c) {
    disturb();
    sync_level_vector(m_map.usart.vector_rxc, m_usart.rxc(), c);
    sync_level_vector(m_map.usart.vector_udre, m_usart.udre(), c);
    sync_level_vector(m_map.usart.vector_txc, m_usart.txc(), c);
}

void AvrChip::usart_txd(Cycle c, bool level) {
    disturb();
    record(c, kTxdLine, level);
}

void AvrChip::timer_flag(char timer, TimerFlag flag, Cycle c) {
    m_quiet_flags_stale = true;
    if (!quiet_flag(timer, flag)) disturb();
    raise(timer_vector(timer - '0', flag), c);
}

int AvrChip::timer_vector(int timer, TimerFlag flag) const {
    return m_map.vector[timer][static_cast<int>(flag)];
}

void AvrChip::timer_output(char, Cycle c) {
    if (m_skipper && m_skipper->pins_read()) m_skipper->disturb();
    update_lines(c);
}

// ---- ports and output lines ----

std::optional<std::size_t> AvrChip::port_reg_index(std::uint16_t addr) const {
    for (std::size_t p = 0; p < m_map.ports.size(); ++p) {
        const std::uint16_t pin = m_map.ports[p].pin;
        if (addr >= pin && addr < pin + 3) return 3 * p + (addr - pin);
    }
    return std::nullopt;
}

void AvrChip::port_write(std::uint16_t addr, std::uint8_t v) {
    const std::size_t i = *port_reg_index(addr);
    if (i % 3 == 0) {  // PINx: writing a one toggles the PORTx bit (SBI: only the addressed bit; CBI: nothing)
        bool set = false;
        if (const auto bit = single_bit_instruction(addr, &set)) v = set ? static_cast<std::uint8_t>(1U << *bit) : 0;
    }
    if (m_port_hooks->write[i] != nullptr)
        m_port_hooks->write[i](m_avr, addr, v, m_port_hooks->write_param[i]);
    else
        m_avr->data[addr] = v;
    update_lines(now());
}

std::uint8_t AvrChip::port_read(std::uint16_t addr) {  // PINx only
    const std::size_t i = *port_reg_index(addr);
    std::uint8_t v = m_port_hooks->read[i] != nullptr ? m_port_hooks->read[i](m_avr, addr, m_port_hooks->read_param[i])
                                                      : m_avr->data[addr];
    // Every pin reads its level: an output its PORT bit or connected compare output, an input its external drive
    // or, undriven, its pull-up (simavr 1.6 reads an undriven input as 0 whatever PORTx says).
    const char port = m_map.ports[i / 3].port;
    for (int bit = 0; bit < 8; ++bit) {
        v = static_cast<std::uint8_t>(pin_level(Pin{port, bit}) ? (v | (1U << bit)) : (v & ~(1U << bit)));
    }
    return v;
}

AvrChip::PinSource AvrChip::pin_source(const Pin& p) const {
    PinSource s;
    s.port = port_index(p.port);
    s.ddr = static_cast<std::uint16_t>(m_map.ports[s.port].pin + 1);
    s.port_reg = static_cast<std::uint16_t>(m_map.ports[s.port].pin + 2);
    s.bit = p.bit;
    for (const CompareOutputPin& oc : m_map.compare_outputs) {
        if (oc.port != p.port || oc.bit != p.bit) continue;
        s.oc_timer = m_timers[static_cast<std::size_t>(oc.timer)].get();
        s.oc_channel = oc.channel;
        break;
    }
    return s;
}

bool AvrChip::pin_level(const Pin& p) const {
    return level_of(pin_source(p));
}

bool AvrChip::level_of(const PinSource& s) const {
    const bool output = ((m_avr->data[s.ddr] >> s.bit) & 1U) != 0;
    const bool port = ((m_avr->data[s.port_reg] >> s.bit) & 1U) != 0;
    // Compare outputs (McuMap) override the port value while their COM bits connect them and the DDR bit is set.
    if (output) {
        if (s.oc_timer != nullptr && s.oc_timer->output_connected(s.oc_channel))
            return s.oc_timer->output_level(s.oc_channel);
        return port;
    }
    if (const std::int8_t driven = m_inputs[s.port][static_cast<std::size_t>(s.bit)]; driven >= 0) return driven != 0;
    // An input pin reads its pull-up (PORT bit set) or floats; the DRV8825's STEP, DIR and nENBL inputs have
    // internal pull-downs (DRV8825 datasheet §7.5), so a floating pin is low.
    return port;
}

void AvrChip::update_lines(Cycle c) {
    for (std::size_t i = 0; i < m_line_sources.size(); ++i) record(c, static_cast<int>(i), level_of(m_line_sources[i]));
    if (m_output_listener) m_output_listener(c);
}

void AvrChip::record(Cycle c, int line, bool level) {
    auto& cur = m_level[static_cast<std::size_t>(line)];
    if (cur == level) return;
    cur = level;
    m_events.push_back({c, line, level});
}

}  // namespace cnc::avr
