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
 * API call goes through the {@link CallWatch}, one by one also inside a compound step (a rebuild is about 75 calls,
 * each of which may wait for the audio thread to apply it); a refusal with a documented exception
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
        /** True when the entry is one API call, timed as a whole; a compound entry times each of its calls. */
        final boolean single;

        Entry(String name, int weight, Op op, boolean single) {
            this.name = name;
            this.weight = weight;
            this.op = op;
            this.single = single;
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
        compound("triggerRamp", 5, () -> triggerRamp((float) (0.1 + 0.2 * rnd.nextDouble())));
        // ---- structure
        compound("removeLink + re-add", 4, () -> {
            int i = rnd.nextInt(SoakScene.MASSES + 1);
            api("removeLink", () -> m.removeLink(SoakScene.spring(i)));
            readdSpring(i);
        });
        compound("removeMatAndConnectedLinks + re-add", 3, () -> {
            int i = 1 + rnd.nextInt(SoakScene.MASSES);
            api("removeMatAndConnectedLinks", () -> m.removeMatAndConnectedLinks(SoakScene.mass(i)));
            readdBead(i);
        });
        compound("remove a member of the subset being ramped", 3, () -> {
            triggerRamp((float) (0.1 + 0.2 * rnd.nextDouble()));
            int i = rnd.nextInt(SoakScene.MASSES + 1);
            api("removeLink", () -> m.removeLink(SoakScene.spring(i)));
            Thread.sleep(rnd.nextInt(3));
            readdSpring(i);
        });
        compound("removeContactGroup + addContactGroup", 1, () -> {
            api("removeContactGroup", () -> m.removeContactGroup(SoakScene.BEADS));
            api("addContactGroup", () -> m.addContactGroup(SoakScene.BEADS, SoakScene.SPACING / 4, 0.05, 0.001));
        });
        compound("clearModel + rebuild", 1, this::rebuild);
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
        compound("setSimRate 48000 then 44100", 1, () -> {
            try {
                api("setSimRate(48000)", () -> m.setSimRate(48000));
            } finally {
                api("setSimRate(44100)", () -> m.setSimRate(SoakScene.RATE));
            }
        });
        add("draw_physics", 2, m::draw_physics);
        add("computeStep", 2, m::computeStep);
        compound("two writes under getLock()", 3, () -> {
            Lock lock = m.getLock();
            api("getLock().lock()", lock::lock);
            try {
                String s = spring();
                api("setLinkStiffness under getLock()", () -> m.setLinkStiffness(s, 0.1));
                api("setLinkStiffness under getLock()", () -> m.setLinkStiffness(s, 0.2));
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
        compound("detachAvatar + attachAvatar", 1, () -> {
            api("detachAvatar", ugen::detachAvatar);
            api("attachAvatar", () -> ugen.attachAvatar(SoakScene.PLECTRUM, exchange));
        });
        compound("remove the avatar + re-add", 1, () -> {
            api("removeMatAndConnectedLinks(plectrum)", () -> m.removeMatAndConnectedLinks(SoakScene.PLECTRUM));
            api("addHapticInput3D", () -> m.addHapticInput3D(SoakScene.PLECTRUM,
                    new Vect3D(SoakScene.length() / 2, 0.4, 0), SoakScene.SMOOTHING));
            for (int i = 1; i <= SoakScene.MASSES; i++) {
                String bead = SoakScene.mass(i);
                String pick = SoakScene.pick(i);
                if (ask("matExists", () -> m.matExists(bead))) {
                    api("addContact3D", () -> m.addContact3D(pick, SoakScene.SPHERE, SoakScene.CONTACT_K,
                            SoakScene.CONTACT_Z, SoakScene.PLECTRUM, bead));
                }
            }
            api("attachAvatar", () -> ugen.attachAvatar(SoakScene.PLECTRUM, exchange));
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
        compound("invalid: triggerRamp NaN", 1, () -> triggerRamp(Float.NaN));
        add("invalid: getMatPosition unknown", 2, () -> m.getMatPosition("no-such-mass"));
        add("invalid: setDivergenceCheckInterval 0", 1, () -> m.setDivergenceCheckInterval(0));
    }

    /** An entry that is one API call, timed as a whole. */
    private void add(String name, int weight, Op op) {
        ops.add(new Entry(name, weight, op, true));
    }

    /** An entry of several API calls, each made through {@link #api} or {@link #ask} and timed on its own. */
    private void compound(String name, int weight, Op op) {
        ops.add(new Entry(name, weight, op, false));
    }

    /** Makes one API call of a compound entry, timed on its own; its exceptions pass through. */
    private void api(String what, Runnable call) {
        ask(what, () -> {
            call.run();
            return null;
        });
    }

    /** Makes one API call that returns a value, timed on its own; its exceptions pass through. */
    private <T> T ask(String what, java.util.function.Supplier<T> call) {
        try {
            return watch.call(what, call::get);
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new AssertionError("a Supplier threw a checked exception", e);
        }
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

    /** The ramp controller's {@code triggerRamp}: two API calls. */
    private void triggerRamp(float target) {
        ParamController pc = ask("getParamController", () -> m.getParamController(SoakScene.RAMP));
        if (pc == null) {
            throw new IllegalStateException("soak: the ramp controller is gone (the model was cleared)");
        }
        api("triggerRamp", () -> pc.triggerRamp(target));
    }

    private void readdSpring(int i) {
        String a = SoakScene.mass(i);
        String b = SoakScene.mass(i + 1);
        String s = SoakScene.spring(i);
        if (ask("matExists", () -> m.matExists(a)) && ask("matExists", () -> m.matExists(b))
                && !ask("linkExists", () -> m.linkExists(s))) {
            api("addSpringDamper3D", () -> m.addSpringDamper3D(s, SoakScene.REST, SoakScene.STIFFNESS,
                    SoakScene.DAMPING, a, b));
            api("addLinkToSubset", () -> m.addLinkToSubset(s, SoakScene.STRINGS));
        }
    }

    private void readdBead(int i) {
        String bead = SoakScene.mass(i);
        api("addMass2DPlane", () -> m.addMass2DPlane(bead, 1.0, new Vect3D(i * SoakScene.SPACING, 0, 0),
                new Vect3D()));
        api("addMatToSubset", () -> m.addMatToSubset(bead, SoakScene.BEADS));
        readdSpring(i - 1);
        readdSpring(i);
        if (ask("matExists", () -> m.matExists(SoakScene.PLECTRUM))) {
            api("addContact3D", () -> m.addContact3D(SoakScene.pick(i), SoakScene.SPHERE, SoakScene.CONTACT_K,
                    SoakScene.CONTACT_Z, SoakScene.PLECTRUM, bead));
        }
    }

    /** Clears the model and builds the scene again, as a sketch's "reset" key does; each call timed on its own. */
    private void rebuild() {
        api("clearModel", m::clearModel);
        SoakScene.populate(m, new Vect3D(SoakScene.length() / 2, 0.4, 0), this::api);
        api("init", m::init);
        api("attachAvatar", () -> ugen.attachAvatar(SoakScene.PLECTRUM, exchange));
        report.rebuilds.incrementAndGet();
    }

    /** Repairs a diverged or damaged model (wrong element counts, no ramp controller): rebuild, clear, WARN. */
    private void heal() {
        int links = 2 * SoakScene.MASSES + 1;
        boolean damaged = ask("isDiverged", m::isDiverged)
                || ask("getNumberOfMats", m::getNumberOfMats) != SoakScene.MASSES + 3
                || ask("getNumberOfLinks", m::getNumberOfLinks) != links
                || ask("getParamController", () -> m.getParamController(SoakScene.RAMP)) == null;
        if (damaged) {
            api("setStabilityPolicy(WARN)", () -> m.setStabilityPolicy(StabilityPolicy.WARN));
            rebuild();
            api("clearDivergence", m::clearDivergence);
        }
    }

    @Override
    public void run() {
        while (running) {
            Entry e = pick();
            attempt(e.name, e.op, e.single);
            if (System.nanoTime() - lastHeal > HEAL_EVERY_NANOS) {
                lastHeal = System.nanoTime();
                attempt("heal", this::heal, false);
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

    private void attempt(String name, Op op, boolean single) {
        report.calls.incrementAndGet();
        try {
            if (single) {
                watch.call(name, () -> {
                    op.run();
                    return null;
                });
            } else {
                op.run();
            }
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
