package tactus.audio;

import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Hand-run benchmark for docs/audio.md (not a test; never run by gradle test). Per-call costs are thread CPU
 * time (ThreadMXBean), so time spent descheduled on a busy machine does not count; buffer times are wall
 * time, since that is what an audio deadline sees. Prints:
 * <ol>
 * <li>cost per sample of PhyUGen.tick against bare computeStep() on the same string;</li>
 * <li>the real-time factor of PhyUGen for longer strings (the largest one rendered in real time);</li>
 * <li>per-buffer compute time (p50, p99.9, max, and buffers over their period) for several Minim buffer
 * sizes, paced in real time, while a 1 kHz haptic thread uses the AvatarExchange and a 60 fps "draw"
 * thread reads every mass position through the model's locked getters.</li>
 * </ol>
 * Usage: java -cp CLASSPATH tactus.audio.AudioBench [quick | overhead | realtime | buffers | threads]
 */
public final class AudioBench {
    private static final int RATE = 44100;
    private static boolean quick;
    private static tactus.StabilityPolicy editPolicy = tactus.StabilityPolicy.WARN;

    private AudioBench() {
    }

    /** A plucked string of n Mass2DPlane masses like StringModel, plus an avatar with contacts to a few masses. */
    static PhysicalModel string(int n, boolean avatar) {
        PhysicalModel pm = new PhysicalModel(RATE);
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        int apex = Math.max(1, n / 4);
        for (int i = 1; i <= n; i++) {
            double y = i <= apex ? 0.001 * i / apex : 0.001 * (n + 1 - i) / (n + 1 - apex);
            pm.addMass2DPlane("m" + i, 1, new Vect3D(i * 0.1, y, 0), new Vect3D());
        }
        pm.addGround3D("g" + (n + 1), new Vect3D((n + 1) * 0.1, 0, 0));
        for (int i = 0; i <= n; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == n ? "g" + (n + 1) : "m" + (i + 1);
            pm.addSpringDamper3D("s" + i, 0.05, 0.2, 0.0001, a, b);
        }
        if (avatar) {
            pm.addHapticInput3D("avatar", new Vect3D(0.5, 0.5, 0), 30);
            for (int i = 1; i <= Math.min(n, 70); i++) {
                pm.addContact3D("c" + i, 0.05, 0.01, 0.001, "avatar", "m" + i);
            }
        }
        pm.init();
        return pm;
    }

    /** Thread CPU time: the machine is shared, so time spent descheduled must not count. */
    private static final java.lang.management.ThreadMXBean CPU = java.lang.management.ManagementFactory.getThreadMXBean();

    /** Median CPU ns per call over rounds of roughly 0.1-0.2 s each, after a warm-up. */
    private static double nsPerCall(Runnable r, long callsPerRound) {
        return paired(r, r, callsPerRound)[0];
    }

    /**
     * Runs a and b in alternating rounds (so both see the same machine load) and returns
     * {median ns of a, median ns of b, median ratio b/a, min ratio, max ratio}.
     */
    private static double[] paired(Runnable a, Runnable b, long callsPerRound) {
        int rounds = quick ? 5 : 15;
        for (long i = 0; i < callsPerRound * 2; i++) {
            a.run();
            b.run();
        }
        double[] ta = new double[rounds];
        double[] tb = new double[rounds];
        double[] ratio = new double[rounds];
        for (int k = 0; k < rounds; k++) {
            long t0 = CPU.getCurrentThreadCpuTime();
            for (long i = 0; i < callsPerRound; i++) {
                a.run();
            }
            long t1 = CPU.getCurrentThreadCpuTime();
            for (long i = 0; i < callsPerRound; i++) {
                b.run();
            }
            long t2 = CPU.getCurrentThreadCpuTime();
            ta[k] = (t1 - t0) / (double) callsPerRound;
            tb[k] = (t2 - t1) / (double) callsPerRound;
            ratio[k] = tb[k] / ta[k];
        }
        Arrays.sort(ta);
        Arrays.sort(tb);
        Arrays.sort(ratio);
        return new double[] {ta[rounds / 2], tb[rounds / 2], ratio[rounds / 2], ratio[0], ratio[rounds - 1]};
    }

    private static long callsFor(int n) {
        return Math.max(2000, 40_000_000L / (n + 50));
    }

    public static void main(String[] args) throws Exception {
        quick = args.length > 0 && args[0].equals("quick");
        if (args.length > 0 && args[0].equals("realtime")) {
            realTime(new int[] {3000, 3500, 4000, 4500, 5000});
            return;
        }
        boolean overheadOnly = args.length > 0 && args[0].equals("overhead");
        if (args.length > 0 && args[0].equals("buffers")) {
            bufferTimes(1000);
            return;
        }
        if (args.length > 0 && args[0].equals("editing")) {
            // audio buffers while draw (60 fps), haptics (1 kHz) and an editor (a change every 3 ms) run
            int n = args.length > 1 ? Integer.parseInt(args[1]) : 1000;
            double seconds = args.length > 2 ? Double.parseDouble(args[2]) : 6;
            editPolicy = args.length > 3 ? tactus.StabilityPolicy.valueOf(args[3]) : tactus.StabilityPolicy.WARN;
            System.out.println("## Per-buffer time, " + n + "-mass string with avatar; draw 60 fps, haptic 1 kHz, a "
                    + "parameter change every 3 ms (StabilityPolicy." + editPolicy + ")");
            System.out.println("| audio path | buffer frames | period ms | buffers | p50 ms | p99.9 ms | max ms | "
                    + "buffers over their period | changes made |");
            System.out.println("|---|---|---|---|---|---|---|---|---|");
            for (int bs : new int[] {256, 1024}) {
                editingRun(n, bs, true, seconds);
                editingRun(n, bs, false, seconds);
            }
            return;
        }
        if (args.length > 0 && args[0].equals("topology")) {
            System.out.println("## Stepping calls that apply a queued change (wall ns of that one computeStep())");
            System.out.println("| string masses | plain step p50 ns | parameter change: max ns | call that installs a new plan: p50 ns | its max ns | any call while an editor makes a topology change (add + remove a spring): max ns |");
            System.out.println("|---|---|---|---|---|---|");
            for (int n : new int[] {1000, 10000}) {
                topologyRun(n);
            }
            return;
        }
        if (args.length > 0 && args[0].equals("threads")) {
            // the same paced buffers with no other thread, with the haptic thread, and with haptic + draw
            System.out.println("## Per-buffer time of a 1000-mass string with avatar, by the other threads running");
            System.out.println("| other threads | buffer frames | period ms | buffers | p50 ms | p99.9 ms | max ms | buffers over their period |");
            System.out.println("|---|---|---|---|---|---|---|---|");
            for (int bs : new int[] {256, 1024}) {
                for (int mode = 0; mode < 3; mode++) {
                    bufferRun(1000, bs, mode >= 1, mode >= 2, new String[] {"alone", "haptic", "haptic + draw"}[mode]);
                }
            }
            return;
        }
        System.out.println("JVM " + System.getProperty("java.vm.name") + " " + System.getProperty("java.version") + ", "
                + Runtime.getRuntime().availableProcessors() + " cores");
        System.out.println();
        System.out.println("## PhyUGen cost per sample vs bare computeStep() (CPU ns, paired rounds; overhead = median ratio - 1, min..max)");
        System.out.println("| string masses | computeStep ns | PhyUGen.tick ns | overhead | with avatar + 70 contacts: sketch loop ns | PhyUGen ns | overhead |");
        System.out.println("|---|---|---|---|---|---|---|");
        for (int n : new int[] {70, 1000, 10000}) {
            PhysicalModel bare = string(n, false);
            PhyUGen u = new PhyUGen(string(n, false));
            u.listenToMass("m3", SteppedModel.Y, 100, 0);
            u.setSampleRate(RATE);
            float[] frame = new float[2];
            Vect3D listen = new Vect3D();
            double[] plain = paired(() -> {
                // the bare loop a sketch would write: one step, one listening read
                bare.computeStep();
                bare.getMatPosition("m3", listen);
            }, () -> u.tick(frame), callsFor(n));
            PhysicalModel bareA = string(n, true);
            AvatarExchange exBare = new AvatarExchange();
            Vect3D tgt = new Vect3D(0.5, 0.5, 0);
            PhyUGen ua = new PhyUGen(string(n, true));
            ua.listenToMass("m3", SteppedModel.Y, 100, 0);
            AvatarExchange ex = new AvatarExchange();
            ex.publishPosition(0.5, 0.5, 0);
            ua.attachAvatar("avatar", ex);
            ua.setSampleRate(RATE);
            double[] avatar = paired(() -> {
                // the paper's per-sample sketch code: target, step, listen, take the force
                bareA.setHapticPosition("avatar", tgt);
                bareA.computeStep();
                bareA.getMatPosition("m3", listen);
                Vect3D fv = bareA.getHapticForce("avatar");
                exBare.addForce(fv.x, fv.y, fv.z);
            }, () -> ua.tick(frame), callsFor(n));
            System.out.printf(Locale.ROOT, "| %d | %.0f | %.0f | %+.1f%% (%+.1f..%+.1f) | %.0f | %.0f | %+.1f%% (%+.1f..%+.1f) |%n", n,
                    plain[0], plain[1], 100 * (plain[2] - 1), 100 * (plain[3] - 1), 100 * (plain[4] - 1),
                    avatar[0], avatar[1], 100 * (avatar[2] - 1), 100 * (avatar[3] - 1), 100 * (avatar[4] - 1));
        }
        System.out.println();
        if (overheadOnly) {
            return;
        }
        realTime(new int[] {1000, 2000, 3000, 4000, 5000, 10000, 20000, 40000});
        bufferTimes(1000);
        bufferTimes(10000);
    }

    private static void realTime(int[] sizes) {
        System.out.println("## Real-time factor of PhyUGen (one listening point, mono) on one core (CPU ns)");
        System.out.println("| string masses (elements) | ns per sample | real-time factor (22,676 ns per sample at 44.1 kHz) |");
        System.out.println("|---|---|---|");
        for (int n : sizes) {
            PhyUGen u = new PhyUGen(string(n, false));
            u.listenToMass("m3", SteppedModel.Y, 100, 0);
            u.setSampleRate(RATE);
            float[] frame = new float[1];
            double p = nsPerCall(() -> u.tick(frame), callsFor(n));
            System.out.printf(Locale.ROOT, "| %d (%d) | %.0f | %.2fx |%n", n, 2 * n + 1, p, 1e9 / RATE / p);
        }
        System.out.println();
    }

    /** Paced buffers with a haptic and a draw thread running. */
    private static void bufferTimes(int n) throws Exception {
        System.out.println("## Per-buffer compute time, " + n + "-mass string with avatar, haptic 1 kHz + draw 60 fps running");
        System.out.println("| buffer frames | period ms | buffers | p50 ms | p99.9 ms | max ms | buffers over their period |");
        System.out.println("|---|---|---|---|---|---|---|");
        for (int bs : new int[] {128, 256, 512, 1024, 2048}) {
            bufferRun(n, bs, true, true, null);
        }
        System.out.println();
    }

    private static void bufferRun(int n, int bs, boolean withHaptic, boolean withDraw, String label) throws Exception {
        {
            if (label != null) {
                System.out.print("| " + label + " ");
            }
            PhysicalModel pm = string(n, true);
            PhyUGen u = new PhyUGen(pm);
            u.listenToMass("m3", SteppedModel.Y, 100, 0);
            AvatarExchange ex = new AvatarExchange();
            u.attachAvatar("avatar", ex);
            u.setSampleRate(RATE);
            float[] frame = new float[2];
            for (int i = 0; i < 100_000; i++) {
                u.tick(frame); // warm-up
            }
            double seconds = quick ? 2 : 6;
            int buffers = (int) (seconds * RATE / bs);
            long[] times = new long[buffers];
            long period = Math.round(bs * 1e9 / RATE);
            final java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean();
            Thread haptic = new Thread(() -> {
                double[] f = new double[3];
                long next = System.nanoTime();
                int k = 0;
                while (!stop.get()) {
                    ex.publishPosition(0.5 + 0.001 * Math.sin(k++ * 0.01), 0.5, 0);
                    ex.takeForce(f);
                    next += 1_000_000;
                    LockSupport.parkNanos(next - System.nanoTime());
                }
            }, "haptic");
            Thread draw = new Thread(() -> {
                Vect3D v = new Vect3D();
                long next = System.nanoTime();
                while (!stop.get()) {
                    for (int i = 1; i <= n; i++) {
                        pm.getMatPosition("m" + i, v);
                    }
                    next += 16_666_667;
                    LockSupport.parkNanos(next - System.nanoTime());
                }
            }, "draw");
            haptic.setDaemon(true);
            draw.setDaemon(true);
            if (withHaptic) {
                haptic.start();
            }
            if (withDraw) {
                draw.start();
            }
            long deadline = System.nanoTime();
            int over = 0;
            for (int b = 0; b < buffers; b++) {
                long t0 = System.nanoTime();
                for (int i = 0; i < bs; i++) {
                    u.tick(frame);
                }
                times[b] = System.nanoTime() - t0;
                if (times[b] > period) {
                    over++;
                }
                deadline += period;
                long wait = deadline - System.nanoTime();
                if (wait > 0) {
                    LockSupport.parkNanos(wait);
                }
            }
            stop.set(true);
            if (withHaptic) {
                haptic.join();
            }
            if (withDraw) {
                draw.join();
            }
            Arrays.sort(times);
            System.out.printf(Locale.ROOT, "| %d | %.2f | %d | %.3f | %.3f | %.3f | %d |%n", bs, period / 1e6, buffers,
                    times[buffers / 2] / 1e6, times[(int) Math.min(buffers - 1, Math.floor(buffers * 0.999))] / 1e6,
                    times[buffers - 1] / 1e6, over);
        }
    }

    /**
     * Buffers computed as Minim does while three other threads run: draw() at 60 fps, the haptic loop at 1 kHz and an
     * editor that changes a spring's stiffness every 3 ms. {@code realtime}: a PhyUGen (the model stepped in realtime:
     * the audio thread takes no lock; draw reads getSnapshot(), haptics go through an AvatarExchange, changes are
     * queued). Otherwise the locked path of before: the audio thread holds the model lock around each sample, draw
     * reads every position through the locked getter, haptics call setHapticPosition / getHapticForce, and each change
     * runs its validation and stability analysis under the lock.
     */
    private static void editingRun(int n, int bs, boolean realtime, double seconds) throws Exception {
        PhysicalModel pm = string(n, true);
        pm.setStabilityPolicy(editPolicy);
        AvatarExchange ex = new AvatarExchange();
        PhyUGen u = null;
        if (realtime) {
            u = new PhyUGen(pm);
            u.listenToMass("m3", SteppedModel.Y, 100, 0);
            u.attachAvatar("avatar", ex);
            u.setSampleRate(RATE);
        }
        final PhyUGen ugen = u;
        float[] frame = new float[2];
        Vect3D listen = new Vect3D();
        Vect3D target = new Vect3D(0.5, 0.5, 0);
        java.util.concurrent.locks.Lock lock = pm.getLock();
        Runnable sample = realtime ? () -> ugen.tick(frame) : () -> {
            lock.lock();
            try {
                pm.computeStep();
                pm.getMatPosition("m3", listen);
            } finally {
                lock.unlock();
            }
        };
        for (int i = 0; i < 100_000; i++) {
            sample.run(); // warm-up
        }
        int buffers = (int) (seconds * RATE / bs);
        long[] times = new long[buffers];
        long period = Math.round(bs * 1e9 / RATE);
        java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.atomic.AtomicLong changes = new java.util.concurrent.atomic.AtomicLong();
        Thread haptic = new Thread(() -> {
            double[] f = new double[3];
            Vect3D fv = new Vect3D();
            Vect3D pos = new Vect3D();
            long next = System.nanoTime();
            int k = 0;
            while (!stop.get()) {
                double x = 0.5 + 0.001 * Math.sin(k++ * 0.01);
                if (realtime) {
                    ex.publishPosition(x, 0.5, 0);
                    ex.takeForce(f);
                } else {
                    pm.setHapticPosition("avatar", pos.set(x, 0.5, 0));
                    pm.getHapticForce("avatar", fv);
                }
                next += 1_000_000;
                LockSupport.parkNanos(next - System.nanoTime());
            }
        }, "haptic");
        Thread draw = new Thread(() -> {
            Vect3D v = new Vect3D();
            double sink = 0;
            long next = System.nanoTime();
            while (!stop.get()) {
                if (realtime) {
                    tactus.ModelSnapshot snap = pm.getSnapshot();
                    for (int i = 0; i < snap.getNumberOfMats(); i++) {
                        sink += snap.y(i);
                    }
                } else {
                    for (int i = 1; i <= n; i++) {
                        sink += pm.getMatPosition("m" + i, v).y;
                    }
                }
                next += 16_666_667;
                LockSupport.parkNanos(next - System.nanoTime());
            }
            if (sink == 42) {
                System.out.print("");
            }
        }, "draw");
        Thread editor = new Thread(() -> {
            long next = System.nanoTime();
            int k = 0;
            while (!stop.get()) {
                pm.setLinkStiffness("s" + (k % n), (k & 1) == 0 ? 0.2 : 0.19);
                k++;
                changes.incrementAndGet();
                next += 3_000_000;
                LockSupport.parkNanos(next - System.nanoTime());
            }
        }, "editor");
        for (Thread t : new Thread[] {haptic, draw, editor}) {
            t.setDaemon(true);
            t.start();
        }
        long deadline = System.nanoTime();
        int over = 0;
        for (int b = 0; b < buffers; b++) {
            long t0 = System.nanoTime();
            for (int i = 0; i < bs; i++) {
                sample.run();
            }
            times[b] = System.nanoTime() - t0;
            if (times[b] > period) {
                over++;
            }
            deadline += period;
            long wait = deadline - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
            }
        }
        stop.set(true);
        for (Thread t : new Thread[] {haptic, draw, editor}) {
            t.join();
        }
        Arrays.sort(times);
        System.out.printf(Locale.ROOT, "| %s | %d | %.2f | %d | %.3f | %.3f | %.3f | %d | %d |%n",
                realtime ? "PhyUGen, realtime stepping" : "locked per sample (before)", bs, period / 1e6, buffers,
                times[buffers / 2] / 1e6, times[(int) Math.min(buffers - 1, Math.floor(buffers * 0.999))] / 1e6,
                times[buffers - 1] / 1e6, over, changes.get());
    }

    /** What applying a queued change costs the stepping thread: the step that applies it, parameter vs topology. */
    private static void topologyRun(int n) throws Exception {
        PhysicalModel pm = string(n, false);
        pm.setStabilityPolicy(tactus.StabilityPolicy.OFF);
        pm.beginRealtimeStepping();
        long[] plain = new long[20_000];
        for (int i = 0; i < 50_000; i++) {
            pm.computeStep();
        }
        for (int i = 0; i < plain.length; i++) {
            long t0 = System.nanoTime();
            pm.computeStep();
            plain[i] = System.nanoTime() - t0;
        }
        Arrays.sort(plain);
        long paramMax = 0;
        long topoMax = 0;
        long[] install = new long[40];
        int installs = 0;
        for (int r = 0; r < 20; r++) {
            Thread ed = new Thread(() -> pm.setLinkStiffness("s5", 0.19));
            ed.start();
            ed.join();
            long t0 = System.nanoTime();
            pm.computeStep();
            paramMax = Math.max(paramMax, System.nanoTime() - t0);
            // a structural change waits for the owner: let a helper thread make it while this thread steps
            Thread topo = new Thread(() -> {
                pm.addSpringDamper3D("extra", 0.05, 0.001, 0, "m2", "m4");
                pm.removeLink("extra");
            });
            topo.start();
            while (topo.isAlive()) {
                long i0 = tactus.EngineProbe.preparedInstalls(pm);
                long t1 = System.nanoTime();
                pm.computeStep();
                long dt = System.nanoTime() - t1;
                topoMax = Math.max(topoMax, dt);
                if (tactus.EngineProbe.preparedInstalls(pm) != i0 && installs < install.length) {
                    install[installs++] = dt; // this call swapped in a plan the editor compiled
                }
            }
        }
        long[] inst = Arrays.copyOf(install, installs);
        Arrays.sort(inst);
        System.out.printf(Locale.ROOT, "| %d | %d | %d | %d | %d | %d |%n", n, plain[plain.length / 2], paramMax,
                installs == 0 ? -1 : inst[installs / 2], installs == 0 ? -1 : inst[installs - 1], topoMax);
        pm.endRealtimeStepping();
    }
}
