package tactus.bench;

import ddf.minim.ugens.Summer;
import java.util.Locale;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.faust.FaustCost;

/**
 * Where a small model's audio sample goes (docs/performance.md, "Where a small model's sample goes"): the same 1-D
 * string stepped through layers that each add one part of the audio path, measured interleaved in one JVM, so that
 * the difference between two layers is what that part costs per sample (thread CPU time, so that other load on the
 * machine counts as little as possible):
 * <ol>
 *   <li>the engine alone, {@code Engine.step(n)} over a whole buffer (the physics and the divergence guard);</li>
 *   <li>the block path: the engine recording one position per step ({@code Engine.stepRecording}), the facade's
 *       block call ({@code computeNStepsRecording}, 64 steps per call, realtime mode), a {@code PhyUGen} at block 64
 *       ticked through a Minim {@code Summer};</li>
 *   <li>the per-sample path: the engine, one {@code step(1)} per sample and one position read
 *       ({@code Engine.position});</li>
 *   <li>{@code PhysicalModel.computeStep()} and {@code Mass.getPosition(Vect3D)}, locked mode;</li>
 *   <li>the same in realtime mode (the model's owner, as under a PhyUGen);</li>
 *   <li>the same inside one run of the owner's calls per sample ({@code beginRealtimeCalls}), as a PhyUGen's
 *       sample is;</li>
 *   <li>a {@code PhyUGen} (block 1) ticked through a Minim {@code Summer}, as an output or the OfflineRenderer
 *       ticks it;</li>
 *   <li>Minim alone: a UGen that writes a constant, ticked through a {@code Summer} (what any UGen costs per sample
 *       in Minim: a remainder and a monitor per tick).</li>
 * </ol>
 * Each line says what it adds to the line it builds on.
 *
 * <pre>java -cp build/classes/java/tools:build/classes/java/main:&lt;minim, core jars&gt; tactus.bench.AudioProfile [masses...]</pre>
 */
public final class AudioProfile {
    private static final int BUFFER = 512;
    /** The block of the block layers, in samples: PhyUGen.setBlockSize's recommended 64. */
    private static final int BLOCK = 64;

    /** Minim's own cost per sample: a UGen that writes a constant. */
    private static final class Constant extends ddf.minim.UGen {
        @Override
        protected void uGenerate(float[] channels) {
            java.util.Arrays.fill(channels, 0.25f);
        }
    }
    private static final java.lang.management.ThreadMXBean CPU = java.lang.management.ManagementFactory.getThreadMXBean();

    private AudioProfile() {
    }

    /** Runs the layers for each string size given (default 30 and 100 masses) and prints ns per sample. */
    public static void main(String[] args) {
        int[] sizes = args.length == 0 ? new int[] {30, 100} : java.util.Arrays.stream(args).mapToInt(Integer::parseInt).toArray();
        for (int n : sizes) {
            profile(n);
        }
    }

    private static void profile(int n) {
        Engine engine = engineString(n);
        int listen = 2 * n / 3 + 1;
        PhysicalModel locked = FaustCost.string(n, false);
        Mass lockedMass = locked.getMass("m" + listen);
        PhysicalModel realtime = FaustCost.string(n, false);
        realtime.beginRealtimeStepping();
        Mass realtimeMass = realtime.getMass("m" + listen);
        PhyUGen ugen = new PhyUGen(FaustCost.string(n, false));
        ugen.setBlockSize(1);
        ugen.listenToMass("m" + listen, SteppedModel.Z, 1, 0);
        Summer root = summing(ugen);
        float[] frame = new float[1];
        double[] pos = new double[3];
        Vect3D v = new Vect3D();
        PhysicalModel blockModel = FaustCost.string(n, false);
        blockModel.beginRealtimeStepping();
        Mass[] blockMasses = {blockModel.getMass("m" + listen)};
        int[] blockAxes = {2};
        double[] recorded = new double[BUFFER];
        int[] engineIds = {listen};
        PhyUGen blockUgen = new PhyUGen(FaustCost.string(n, false));
        blockUgen.setBlockSize(BLOCK);
        blockUgen.listenToMass("m" + listen, SteppedModel.Z, 1, 0);
        Summer blockRoot = summing(blockUgen);
        Summer constantRoot = summing(new Constant());
        String[] names = {"Engine.step(512), per step", "Engine.stepRecording(512), per step",
            "computeNStepsRecording(64), realtime", "PhyUGen, block 64, Minim's tick", "Engine.step(1) + position",
            "computeStep + getPosition, locked", "computeStep + getPosition, realtime",
            "the same in one run (beginRealtimeCalls)", "PhyUGen, block 1, Minim's tick",
            "Minim alone: a constant UGen, Summer"};
        // the line each one adds to (-1: none)
        int[] parent = {-1, 0, 1, 2, 0, 4, 5, 6, 7, -1};
        Runnable[] layers = {
            () -> engine.step(BUFFER),
            () -> engine.stepRecording(BUFFER, engineIds, blockAxes, 1, recorded, 0),
            () -> {
                for (int i = 0; i < BUFFER; i += BLOCK) {
                    blockModel.computeNStepsRecording(BLOCK, blockMasses, blockAxes, recorded);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    frame[0] = 0;
                    blockRoot.tick(frame);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    engine.step(1);
                    engine.position(listen, pos);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    locked.computeStep();
                    lockedMass.getPosition(v);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    realtime.computeStep();
                    realtimeMass.getPosition(v);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    boolean run = realtime.beginRealtimeCalls();
                    try {
                        realtime.computeStep();
                        realtimeMass.getPosition(v);
                    } finally {
                        if (run) {
                            realtime.endRealtimeCalls();
                        }
                    }
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    frame[0] = 0;
                    root.tick(frame);
                }
            },
            () -> {
                for (int i = 0; i < BUFFER; i++) {
                    frame[0] = 0;
                    constantRoot.tick(frame);
                }
            }
        };
        int buffersPerRun = Math.max(20, 2_000_000 / (BUFFER * n));
        for (long end = System.nanoTime() + 3_000_000_000L; System.nanoTime() < end; ) {
            for (Runnable r : layers) {
                for (int b = 0; b < buffersPerRun; b++) {
                    r.run();
                }
            }
        }
        int rounds = 15;
        double[][] ns = new double[layers.length][rounds];
        for (int round = 0; round < rounds; round++) {
            for (int k = 0; k < layers.length; k++) {
                int l = (k + round) % layers.length;
                long t0 = CPU.getCurrentThreadCpuTime();
                for (int b = 0; b < buffersPerRun; b++) {
                    layers[l].run();
                }
                ns[l][round] = (CPU.getCurrentThreadCpuTime() - t0) / (double) (buffersPerRun * BUFFER);
            }
        }
        System.out.printf(Locale.ROOT, "1-D string, %d masses (median of %d interleaved rounds, ns of thread CPU time per sample)%n", n, rounds);
        double[] med = new double[layers.length];
        for (int l = 0; l < layers.length; l++) {
            java.util.Arrays.sort(ns[l]);
            med[l] = ns[l][rounds / 2];
            String added = parent[l] < 0 ? "" : String.format(Locale.ROOT, "(+%.1f on \"%s\")", med[l] - med[parent[l]],
                    names[parent[l]]);
            System.out.printf(Locale.ROOT, "  %-40s %8.1f  [%.1f-%.1f]  %s%n", names[l], med[l], ns[l][0],
                    ns[l][rounds - 1], added);
        }
    }

    /** @return a mono {@code Summer} at 44.1 kHz with the UGens patched into it, as an output ticks them. */
    static Summer summing(ddf.minim.UGen... us) {
        Summer root = new Summer();
        for (ddf.minim.UGen u : us) {
            u.patch(root);
            u.setSampleRate(44100);
            u.setChannelCount(1);
        }
        root.setSampleRate(44100);
        root.setChannelCount(1);
        return root;
    }

    private static Engine engineString(int n) {
        Engine e = new Engine();
        int g0 = e.addMass(MassKind.GROUND1D, 1, 0, 0, 0, 0, 0, 0);
        int[] ids = new int[n + 2];
        ids[0] = g0;
        for (int i = 1; i <= n; i++) {
            ids[i] = e.addMass(MassKind.MASS1D, 1, i, 0, i == n / 5 + 1 ? 1e-3 : 0, 0, 0, 0);
        }
        ids[n + 1] = e.addMass(MassKind.GROUND1D, 1, n + 1, 0, 0, 0, 0, 0);
        for (int i = 0; i <= n; i++) {
            e.addLink(LinkKind.SPRING_DAMPER1D, ids[i], ids[i + 1], 0.2, 0.0005, 0);
        }
        e.compile();
        return e;
    }
}
