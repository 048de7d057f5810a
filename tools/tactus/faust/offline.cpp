/*
 * Tactus's offline Faust architecture (our own code, used by tactus.faust.FaustToolchain and its tests):
 * renders N samples of the exported program and prints them, one line per sample, every output as %.17g.
 *
 *   prog N [-in CHANNEL SAMPLE VALUE]... [-set LABEL VALUE]... [-bench] [-voices V]
 *
 * -in puts VALUE on input CHANNEL at sample SAMPLE (every other input sample is 0); -set sets a slider before
 * the first sample; -bench renders N samples in blocks of 256 (after an untimed warm-up of N/10 samples) and
 * prints only the nanoseconds per sample, of wall-clock time and then of the process's CPU time; -voices V
 * (with -bench) renders V instances of the program side by side, each block of each in turn, like V voices
 * of a synthesiser, and the figures are per sample of all V.
 */
#define FAUSTFLOAT double
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>
#include <algorithm>
#include <faust/dsp/dsp.h>
#include <faust/gui/UI.h>
#include <faust/gui/meta.h>

/* Collects the zones of the sliders by label. */
struct SliderZones : public UI {
    std::map<std::string, FAUSTFLOAT*> zones;
    void openTabBox(const char*) {}
    void openHorizontalBox(const char*) {}
    void openVerticalBox(const char*) {}
    void closeBox() {}
    void addButton(const char* l, FAUSTFLOAT* z) { zones[l] = z; }
    void addCheckButton(const char* l, FAUSTFLOAT* z) { zones[l] = z; }
    void addVerticalSlider(const char* l, FAUSTFLOAT* z, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT) { zones[l] = z; }
    void addHorizontalSlider(const char* l, FAUSTFLOAT* z, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT) { zones[l] = z; }
    void addNumEntry(const char* l, FAUSTFLOAT* z, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT, FAUSTFLOAT) { zones[l] = z; }
    void addHorizontalBargraph(const char*, FAUSTFLOAT*, FAUSTFLOAT, FAUSTFLOAT) {}
    void addVerticalBargraph(const char*, FAUSTFLOAT*, FAUSTFLOAT, FAUSTFLOAT) {}
    void addSoundfile(const char*, const char*, Soundfile**) {}
    void declare(FAUSTFLOAT*, const char*, const char*) {}
};

<<includeIntrinsic>>

<<includeclass>>

int main(int argc, char* argv[]) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s N [-in CHANNEL SAMPLE VALUE]... [-set LABEL VALUE]... [-bench]\n", argv[0]);
        return 2;
    }
    long n = atol(argv[1]);
    mydsp dsp;
    dsp.init(44100);
    SliderZones ui;
    dsp.buildUserInterface(&ui);
    int ni = dsp.getNumInputs();
    int no = dsp.getNumOutputs();
    struct Event { int channel; long sample; double value; };
    std::vector<Event> events;
    bool bench = false;
    int voices = 1;
    for (int a = 2; a < argc; a++) {
        if (!strcmp(argv[a], "-in") && a + 3 < argc) {
            Event e = { atoi(argv[a + 1]), atol(argv[a + 2]), strtod(argv[a + 3], nullptr) };
            if (e.channel < 0 || e.channel >= ni) { fprintf(stderr, "no input %d\n", e.channel); return 2; }
            events.push_back(e);
            a += 3;
        } else if (!strcmp(argv[a], "-set") && a + 2 < argc) {
            auto z = ui.zones.find(argv[a + 1]);
            if (z == ui.zones.end()) { fprintf(stderr, "no slider %s\n", argv[a + 1]); return 2; }
            *z->second = strtod(argv[a + 2], nullptr);
            a += 2;
        } else if (!strcmp(argv[a], "-bench")) {
            bench = true;
        } else if (!strcmp(argv[a], "-voices") && a + 1 < argc) {
            voices = atoi(argv[a + 1]);
            if (voices < 1) { fprintf(stderr, "-voices needs at least 1\n"); return 2; }
            a += 1;
        } else {
            fprintf(stderr, "unknown argument %s\n", argv[a]);
            return 2;
        }
    }
    const int block = bench ? 256 : 1;
    std::vector<std::vector<double>> in(std::max(ni, 1), std::vector<double>(block, 0.0));
    std::vector<std::vector<double>> out(std::max(no, 1), std::vector<double>(block, 0.0));
    std::vector<double*> ip(std::max(ni, 1)), op(std::max(no, 1));
    for (int c = 0; c < ni; c++) ip[c] = in[c].data();
    for (int c = 0; c < no; c++) op[c] = out[c].data();
    std::vector<mydsp*> others;
    for (int v = 1; v < voices; v++) {
        others.push_back(new mydsp());
        others.back()->init(44100);
    }
    double sink = 0;
    if (bench) {
        for (long s = 0; s < n / 10; s += block) {       // warm-up: caches and branch predictors
            int count = (int) std::min<long>(block, n / 10 - s);
            dsp.compute(count, ip.data(), op.data());
            for (mydsp* o : others) o->compute(count, ip.data(), op.data());
        }
    }
    auto t0 = std::chrono::steady_clock::now();
    std::clock_t c0 = std::clock();
    for (long s = 0; s < n; s += block) {
        int count = (int) std::min<long>(block, n - s);
        for (int c = 0; c < ni; c++) std::fill(in[c].begin(), in[c].end(), 0.0);
        for (const Event& e : events) {
            if (e.sample >= s && e.sample < s + count) in[e.channel][e.sample - s] = e.value;
        }
        dsp.compute(count, ip.data(), op.data());
        if (bench) {
            sink += out[0][0];
            for (mydsp* o : others) {
                o->compute(count, ip.data(), op.data());
                sink += out[0][0];
            }
        } else {
            for (int i = 0; i < count; i++) {
                for (int c = 0; c < no; c++) printf(c ? " %.17g" : "%.17g", out[c][i]);
                printf("\n");
            }
        }
    }
    std::clock_t c1 = std::clock();
    auto t1 = std::chrono::steady_clock::now();
    if (bench) {
        double ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
        double cpu = (double) (c1 - c0) * 1e9 / CLOCKS_PER_SEC / n;
        printf("%.3f ns/sample (cpu %.3f ns/sample, checksum %g)\n", ns, cpu, sink);
    }
    for (mydsp* o : others) delete o;
    return 0;
}
