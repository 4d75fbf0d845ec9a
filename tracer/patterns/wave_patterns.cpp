// Ripples and waves: POV-Ray 3.7's sums of circular waves from ten fixed sources.
#include "tracer/patterns/pattern_functions.hpp"

#include <cmath>

namespace crt::tracer::patterns {

namespace {

/// POV-Ray 3.7's wave sources, near the origin (its number_of_waves default, 10), and
/// each one's own frequency for `waves`: the values its noise gradients and random numbers
/// give them, so that a ported scene shows the same rings.
struct WaveSource {
    Vec3 position;
    double frequency;
};
constexpr WaveSource kWaveSources[] = {
    {{-0.6043782132577583, 0.4920484080339806, -0.6265902484802848}, 0.9191158787805639},
    {{-0.552573104174574, -0.24607533873593257, -0.7963101733676843}, 0.96004119998788},
    {{-0.4445510850547654, 0.6233289848385765, 0.6433003260039127}, 0.43316965239421595},
    {{0.4965860669098816, 0.6689481632688099, 0.5530918847806939}, 0.709301126133064},
    {{-0.06437181420276793, -0.8059515778620631, -0.5884711748912561}, 0.6891894283883799},
    {{0.2461902144060548, -0.9145567834798555, -0.32089915568863925}, 0.991444746238684},
    {{-0.6660889521854475, -0.5918785631447935, -0.4538780389775951}, 0.782972808008128},
    {{-0.5204892024750659, -0.38602713558619195, -0.7616259191348398}, 0.400667439802276},
    {{0.13794944733959097, -0.7046421066818683, -0.6960240308133333}, 0.22967223120824798},
    {{0.5648967309620444, 0.7220405140646138, -0.39943607673531945}, 0.168513138218344},
};
constexpr double kWaveCount = static_cast<double>(std::size(kWaveSources));

/// The distance to a source, 1 at the source itself (as POV-Ray has it).
double distanceTo(const Vec3& p, const WaveSource& source) {
    double length = glm::length(p - source.position);
    return length == 0 ? 1 : length;
}

double cycle(double x) {
    return std::sin(2 * kPi * x);
}

} // namespace

// Both read frequency and phase inside, at each source, as POV-Ray does; its frequency and
// phase then shape the sum once more, as every pattern's.
double ripples(const Vec3& p, double frequency, double phase) {
    double sum = 0;
    for (const WaveSource& source : kWaveSources)
        sum += cycle(distanceTo(p, source) * frequency + phase);
    return 0.5 * (1 + sum / kWaveCount);
}

double waves(const Vec3& p, double frequency, double phase) {
    double sum = 0;
    for (const WaveSource& source : kWaveSources) {
        sum +=
            cycle(distanceTo(p, source) * frequency * source.frequency + phase) / source.frequency;
    }
    return 0.2 * (2.5 + sum / kWaveCount);
}

} // namespace crt::tracer::patterns
