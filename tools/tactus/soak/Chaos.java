package tactus.soak;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.locks.Lock;

import tactus.ParamController;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.Vect3D;
import tactus.audio.AvatarExchange;
import tactus.audio.ListeningPoint;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;

/**
 * The fourth thread: what a sketch's sliders, keys and mistakes do to a playing model, at random (seeded). Each
 * call goes through the {@link CallWatch}; a refusal with a documented exception
 * ({@code IllegalArgumentException}, {@code IllegalStateException} and their subclasses) is counted as such, any
 * other exception is an escape. Valid calls: parameter edits, subset changes, ramps, removals and re-adds of
 * springs and beads (also of a member of the subset being ramped), divergence listeners (quiet, throwing, or
 * ending realtime stepping), {@code setSimRate}, {@code init}, {@code clearModel} and rebuild, stepping calls
 * while the audio thread steps, two writes under {@code getLock()}, stability queries, listening points and the
 * avatar. Invalid calls: unknown names, NaN and negative values, duplicate names, zero rates.
 */
final class Chaos implements Runnable {
    /** One kind of call. */
    private interface Op {
        void run() throws Exception;
    }

    private static final class Entry {
        final String name;
        final int weight;
        final Op op;

        Entry(String name, int weight, Op op) {
            this.name = name;
            this.weight = weight;
            this.op = op;
        }
    }

    /** How often the model is repaired and rebuilt if it needs it, ns. */
    private static final long HEAL_EVERY_NANOS = 2_000_000_000L;

    private final PhysicalModel m;
    private final PhyUGen ugen;
    private final AvatarExchange exchange;
    private final SoakReport report;
    private final CallWatch watch;
    private final Random rnd;
    private final List<Entry> ops = new ArrayList<>();
    private final int totalWeight;
    private final List<ListeningPoint> extraPoints = new ArrayList<>();
    private volatile boolean running = true;
    private long lastHeal = System.nanoTime();

    /**
     * @param skip calls whose name matches it are left out (null: none), to look past a failure that ends the run's
     *     usefulness early, e.g. {@code --skip='ramped|getLock'}
     */
    Chaos(PhysicalModel m, PhyUGen ugen, AvatarExchange exchange, SoakReport report, CallWatch watch, long seed,
          java.util.regex.Pattern skip) {
        this.m = m;
        this.ugen = ugen;
        this.exchange = exchange;
        this.report = report;
        this.watch = watch;
        this.rnd = new Random(seed);
        define();
        if (skip != null) {
            ops.removeIf(e -> skip.matcher(e.name).find());
        }
        if (ops.isEmpty()) {
            throw new IllegalArgumentException("--skip leaves no call to make");
        }
        int w = 0;
        for (Entry e : ops) {
            w += e.weight;
        }
        totalWeight = w;
    }

    void stop() {
        running = false;
    }

    private void define() {
        // ---- valid parameter edits
        add("setLinkStiffness", 10, () -> m.setLinkStiffness(spring(), 0.05 + 0.3 * rnd.nextDouble()));
        add("setLinkDamping", 6, () -> m.setLinkDamping(spring(), 0.001 * rnd.nextDouble()));
        add("setLinkParams", 3, () -> m.setLinkParams(spring(), 0.1 + 0.2 * rnd.nextDouble(), 0.0001,
                SoakScene.REST));
        add("setMatPosition", 6, () -> m.setMatPosition(bead(), new Vect3D(beadIndex() * SoakScene.SPACING,
                0.2 * (rnd.nextDouble() - 0.5), 0)));
        add("triggerForceImpulse", 5, () -> m.triggerForceImpulse(bead(), 0, rnd.nextGaussian() * 0.05, 0));
        add("changeStiffnessParamOfSubset", 3, () -> m.changeStiffnessParamOfSubset(0.1 + 0.2 * rnd.nextDouble(),
                SoakScene.STRINGS));
        add("setFriction", 1, () -> m.setFriction(0.00001 * rnd.nextDouble()));
        add("triggerRamp", 5, () -> ramp().triggerRamp((float) (0.1 + 0.2 * rnd.nextDouble())));
        // ---- structure
        add("removeLink + re-add", 4, () -> {
            int i = rnd.nextInt(SoakScene.MASSES + 1);
            m.removeLink(SoakScene.spring(i));
            readdSpring(i);
        });
        add("removeMatAndConnectedLinks + re-add", 3, () -> {
            int i = 1 + rnd.nextInt(SoakScene.MASSES);
            m.removeMatAndConnectedLinks(SoakScene.mass(i));
            readdBead(i);
        });
        add("remove a member of the subset being ramped", 3, () -> {
            ramp().triggerRamp((float) (0.1 + 0.2 * rnd.nextDouble()));
            int i = rnd.nextInt(SoakScene.MASSES + 1);
            m.removeLink(SoakScene.spring(i));
            Thread.sleep(rnd.nextInt(3));
            readdSpring(i);
        });
        add("removeContactGroup + addContactGroup", 1, () -> {
            m.removeContactGroup(SoakScene.BEADS);
            m.addContactGroup(SoakScene.BEADS, SoakScene.SPACING / 4, 0.05, 0.001);
        });
        add("clearModel + rebuild", 1, this::rebuild);
        add("init", 1, m::init);
        // ---- listeners
        add("listener: quiet", 2, () -> m.setDivergenceListener(e -> report.divergences.incrementAndGet()));
        add("listener: throws", 2, () -> m.setDivergenceListener(e -> {
            report.divergences.incrementAndGet();
            report.listenerThrows.incrementAndGet();
            throw new IllegalStateException("soak: this divergence listener throws on purpose");
        }));
        add("listener: ends realtime stepping", 1, () -> m.setDivergenceListener(e -> {
            report.divergences.incrementAndGet();
            m.endRealtimeStepping();
        }));
        add("listener: none", 1, () -> m.setDivergenceListener(null));
        add("make it diverge", 1, () -> m.setLinkStiffness(spring(), 50));
        add("setStabilityPolicy", 2, () -> m.setStabilityPolicy(StabilityPolicy.values()[rnd.nextInt(
                StabilityPolicy.values().length)]));
        // ---- rates and stepping from the wrong thread
        add("setSimRate 48000 then 44100", 1, () -> {
            try {
                m.setSimRate(48000);
            } finally {
                m.setSimRate(SoakScene.RATE);
            }
        });
        add("draw_physics", 2, m::draw_physics);
        add("computeStep", 2, m::computeStep);
        add("two writes under getLock()", 3, () -> {
            Lock lock = m.getLock();
            lock.lock();
            try {
                String s = spring();
                m.setLinkStiffness(s, 0.1);
                m.setLinkStiffness(s, 0.2);
            } finally {
                lock.unlock();
            }
        });
        // ---- queries from this thread too
        add("describeStability", 2, m::describeStability);
        add("getStabilityReport", 2, m::getStabilityReport);
        add("getTotalEnergy", 3, m::getTotalEnergy);
        add("getMatPosition", 3, () -> m.getMatPosition(bead()));
        // ---- audio side
        add("listenToMass", 2, () -> {
            if (extraPoints.size() < 4) {
                extraPoints.add(ugen.listenToMass(bead(), SteppedModel.Y, 1, 0));
            }
        });
        add("removeListeningPoint", 2, () -> {
            if (!extraPoints.isEmpty()) {
                ugen.removeListeningPoint(extraPoints.remove(rnd.nextInt(extraPoints.size())));
            }
        });
        add("detachAvatar + attachAvatar", 1, () -> {
            ugen.detachAvatar();
            ugen.attachAvatar(SoakScene.PLECTRUM, exchange);
        });
        add("remove the avatar + re-add", 1, () -> {
            m.removeMatAndConnectedLinks(SoakScene.PLECTRUM);
            m.addHapticInput3D(SoakScene.PLECTRUM, new Vect3D(SoakScene.length() / 2, 0.4, 0), SoakScene.SMOOTHING);
            for (int i = 1; i <= SoakScene.MASSES; i++) {
                if (m.matExists(SoakScene.mass(i))) {
                    m.addContact3D(SoakScene.pick(i), SoakScene.SPHERE, SoakScene.CONTACT_K, SoakScene.CONTACT_Z,
                            SoakScene.PLECTRUM, SoakScene.mass(i));
                }
            }
            ugen.attachAvatar(SoakScene.PLECTRUM, exchange);
        });
        // ---- invalid calls: each must be refused on this thread, with the model unchanged
        add("invalid: setLinkStiffness unknown", 3, () -> m.setLinkStiffness("no-such-spring", 0.1));
        add("invalid: setLinkStiffness negative", 2, () -> m.setLinkStiffness(spring(), -1));
        add("invalid: setLinkStiffness NaN", 2, () -> m.setLinkStiffness(spring(), Double.NaN));
        add("invalid: setMatPosition NaN", 2, () -> m.setMatPosition(bead(), new Vect3D(Double.NaN, 0, 0)));
        add("invalid: removeLink unknown", 2, () -> m.removeLink("no-such-spring"));
        add("invalid: addSpringDamper3D to unknown masses", 2, () -> m.addSpringDamper3D("bad", 1, 0.1, 0,
                "no-such-mass", "no-such-mass-2"));
        add("invalid: duplicate mass", 2, () -> m.addMass2DPlane(SoakScene.mass(1), 1, new Vect3D(), new Vect3D()));
        add("invalid: setSimRate 0", 1, () -> m.setSimRate(0));
        add("invalid: subset unknown", 2, () -> m.changeParamOfSubset(0.1, "no-such-subset", "stiffness"));
        add("invalid: param unknown", 1, () -> m.changeParamOfSubset(0.1, SoakScene.STRINGS, "colour"));
        add("invalid: triggerRamp NaN", 1, () -> ramp().triggerRamp(Float.NaN));
        add("invalid: getMatPosition unknown", 2, () -> m.getMatPosition("no-such-mass"));
        add("invalid: setDivergenceCheckInterval 0", 1, () -> m.setDivergenceCheckInterval(0));
    }

    private void add(String name, int weight, Op op) {
        ops.add(new Entry(name, weight, op));
    }

    private String spring() {
        return SoakScene.spring(rnd.nextInt(SoakScene.MASSES + 1));
    }

    private int lastBead = 1;

    private int beadIndex() {
        return lastBead;
    }

    private String bead() {
        lastBead = 1 + rnd.nextInt(SoakScene.MASSES);
        return SoakScene.mass(lastBead);
    }

    private ParamController ramp() {
        ParamController pc = m.getParamController(SoakScene.RAMP);
        if (pc == null) {
            throw new IllegalStateException("soak: the ramp controller is gone (the model was cleared)");
        }
        return pc;
    }

    private void readdSpring(int i) {
        String a = SoakScene.mass(i);
        String b = SoakScene.mass(i + 1);
        if (m.matExists(a) && m.matExists(b) && !m.linkExists(SoakScene.spring(i))) {
            m.addSpringDamper3D(SoakScene.spring(i), SoakScene.REST, SoakScene.STIFFNESS, SoakScene.DAMPING, a, b);
            m.addLinkToSubset(SoakScene.spring(i), SoakScene.STRINGS);
        }
    }

    private void readdBead(int i) {
        m.addMass2DPlane(SoakScene.mass(i), 1.0, new Vect3D(i * SoakScene.SPACING, 0, 0), new Vect3D());
        m.addMatToSubset(SoakScene.mass(i), SoakScene.BEADS);
        readdSpring(i - 1);
        readdSpring(i);
        if (m.matExists(SoakScene.PLECTRUM)) {
            m.addContact3D(SoakScene.pick(i), SoakScene.SPHERE, SoakScene.CONTACT_K, SoakScene.CONTACT_Z,
                    SoakScene.PLECTRUM, SoakScene.mass(i));
        }
    }

    /** Clears the model and builds the scene again, as a sketch's "reset" key does. */
    private void rebuild() {
        m.clearModel();
        SoakScene.populate(m, new Vect3D(SoakScene.length() / 2, 0.4, 0));
        m.init();
        ugen.attachAvatar(SoakScene.PLECTRUM, exchange);
        report.rebuilds.incrementAndGet();
    }

    /** Repairs a diverged or damaged model (wrong element counts, no ramp controller): rebuild, clear, WARN. */
    private void heal() throws Exception {
        watch.call("heal: rebuild + clearDivergence", () -> {
            int links = 2 * SoakScene.MASSES + 1;
            boolean damaged = m.isDiverged() || m.getNumberOfMats() != SoakScene.MASSES + 3
                    || m.getNumberOfLinks() != links || m.getParamController(SoakScene.RAMP) == null;
            if (damaged) {
                m.setStabilityPolicy(StabilityPolicy.WARN);
                rebuild();
                m.clearDivergence();
            }
            return null;
        });
    }

    @Override
    public void run() {
        while (running) {
            Entry e = pick();
            attempt(e.name, e.op);
            if (System.nanoTime() - lastHeal > HEAL_EVERY_NANOS) {
                lastHeal = System.nanoTime();
                attempt("heal", this::heal);
            }
            try {
                Thread.sleep(rnd.nextInt(4));
            } catch (InterruptedException ie) {
                return;
            }
        }
    }

    private Entry pick() {
        int r = rnd.nextInt(totalWeight);
        for (Entry e : ops) {
            r -= e.weight;
            if (r < 0) {
                return e;
            }
        }
        return ops.get(ops.size() - 1);
    }

    private void attempt(String name, Op op) {
        report.calls.incrementAndGet();
        try {
            watch.call(name, () -> {
                op.run();
                return null;
            });
        } catch (IllegalArgumentException | IllegalStateException documented) {
            report.refused(documented);
        } catch (InterruptedException ie) {
            Thread.currentThread().interrupt();
            running = false;
        } catch (Throwable t) {
            report.escape("chaos thread, call '" + name + "' (undocumented exception type)", t);
        }
    }
}
