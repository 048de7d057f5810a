package tactus.engine;

import java.util.Arrays;

/**
 * The mass-interaction simulation, in algorithmic (per-step) units, addressed by integer ids.
 *
 * <p>Masses and links are added by kind and receive a stable id that is never reused. The
 * scene is compiled lazily into a {@link StepPlan} before the next step whenever its topology
 * changed; parameter changes are written straight into the compiled arrays. Each step runs the
 * two phases of the explicit scheme: every mass moves using the forces of the previous
 * interaction phase, then every interaction computes new forces from the new positions.
 *
 * <p>This class does no name handling, unit conversion or locking: the {@code tactus} facade
 * does that. Ids passed in must be live, or an {@link IllegalArgumentException} is thrown.
 */
public final class Engine implements AutoCloseable {
    /** Closes the parallel stepper of an engine that became unreachable without {@link #close()}. */
    private static final java.lang.ref.Cleaner CLEANER = java.lang.ref.Cleaner.create();

    private final MassTable masses = new MassTable();
    private final LinkTable links = new LinkTable();
    private final Medium medium = new Medium();
    private final java.util.ArrayList<ContactGroupSpec> groups = new java.util.ArrayList<>();
    private StepPlan plan;
    private boolean topologyDirty = true;
    // the links of each mass (CSR over link ids), built when first needed after links or masses were added
    private int[] incidenceStart = new int[1];
    private int[] incidence = new int[0];
    private int incidenceLinks = -1;
    private int incidenceMasses = -1;
    private long incidenceBuilds;
    private long compiles;
    /** Counts topology changes, so that a plan prepared on another thread can tell it is still current. */
    private long topologyVersion;
    /** True while a topology change waits for a plan another thread prepares: keep stepping the old plan. */
    private boolean holdTopology;
    private long installs;
    private boolean effectsDirty;
    private long steps;
    private long linkParameterEdits;
    private boolean stencils = true;
    private boolean sweeps = true;
    private ParallelStepper stepper;
    private java.lang.ref.Cleaner.Cleanable stepperCleanup;
    private int parallelMinElements = 20_000;
    private StepModeChooser modes = new StepModeChooser(System::nanoTime);
    private StepPlan hookPlan;
    private long hookSteps;
    private final ParallelStepper.StepHook guardHook = this::afterParallelStep;
    private final DivergenceGuard guard = new DivergenceGuard();
    private int countdown = guard.interval();
    private int divergedMass = -1;
    private long divergedAt = -1;
    /** Scratch of {@link #makeFixed}, a structural change (made by the thread that applies changes). */
    private final double[] scratchA = new double[3];
    /** The plan slots of the masses {@link #stepRecording} reads (grown only when more masses are read). */
    private int[] recordSlots = new int[4];

    /** Creates an empty engine with no gravity and no friction. */
    public Engine() {
    }

    // ------------------------------------------------------------------ medium

    /** Sets the gravity acceleration vector, in units per step squared; masses accelerate along it. */
    public void setGravity(double gx, double gy, double gz) {
        boolean had = medium.hasGravity();
        medium.gx = gx;
        medium.gy = gy;
        medium.gz = gz;
        if (had != medium.hasGravity()) {
            effectsDirty = true;
        }
    }

    /** @return the gravity acceleration component along axis 0, 1 or 2, in units per step squared. */
    public double gravity(int axis) {
        return axis == 0 ? medium.gx : axis == 1 ? medium.gy : medium.gz;
    }

    /** Sets the air friction coefficient (per-step damping against the fixed frame) of every mass. */
    public void setFriction(double f) {
        boolean had = medium.hasFriction();
        medium.friction = f;
        if (had != medium.hasFriction()) {
            effectsDirty = true;
        }
        if (plan != null) {
            for (int s = 0; s < plan.nMass; s++) {
                PlanCompiler.fillMass(plan, s, masses, plan.massId[s], medium);
            }
        }
    }

    /** @return the air friction coefficient, per step. */
    public double friction() {
        return medium.friction;
    }

    // ------------------------------------------------------------------ building

    /**
     * Adds a mass-type module.
     *
     * @param kind the module kind
     * @param mass the inertia M (ignored for fixed and input kinds)
     * @param x initial position
     * @param vx initial displacement per step: the previous position is set to {@code x - vx}
     * @return the new mass id
     */
    public int addMass(MassKind kind, double mass, double x, double y, double z, double vx, double vy, double vz) {
        int id = masses.add(kind, mass);
        boolean fixed = kind.isFixed();
        boolean plane = kind == MassKind.MASS2D_PLANE;
        boolean line = kind == MassKind.MASS1D || kind == MassKind.OSC1D;
        double pvx = fixed || line ? 0 : vx;
        double pvy = fixed || line ? 0 : vy;
        double pvz = fixed || plane ? 0 : vz;
        masses.setPending(id, x, y, z, x - pvx, y - pvy, z - pvz);
        masses.setRest(id, x, y, z);
        masses.weight[id] = 1.0;
        markTopology();
        return id;
    }

    /** Sets the internal stiffness and damping of an oscillator, per step. */
    public void setOscillator(int id, double stiffness, double damping) {
        checkMass(id);
        masses.stiffness[id] = stiffness;
        masses.damping[id] = damping;
        refreshMass(id);
    }

    /** Sets the EWMA weight of an input module: 1 follows the target at once, 1/s smooths over about s steps. */
    public void setInputWeight(int id, double weight) {
        checkMass(id);
        masses.weight[id] = weight;
        refreshMass(id);
    }

    /**
     * Adds an interaction between two masses. {@code length} is the rest length, contact
     * threshold, bubble radius or attractor limit distance, depending on the kind.
     *
     * @return the new link id
     */
    public int addLink(LinkKind kind, int massA, int massB, double stiffness, double damping, double length) {
        checkMass(massA);
        if (!kind.isSingleMass()) {
            checkMass(massB);
        }
        int id = links.add(kind, massA, kind.isSingleMass() ? massA : massB, stiffness, damping, length);
        markTopology();
        return id;
    }

    /** Adds a one-sided plane contact on axis 0, 1 or 2 at coordinate {@code position}, with offset {@code l0}. */
    public int addPlaneContact(int mass, int axis, double position, double l0, double stiffness, double damping) {
        if (axis < 0 || axis > 2) {
            throw new IllegalArgumentException("plane axis must be 0, 1 or 2, got " + axis);
        }
        int id = addLink(LinkKind.PLANE_CONTACT3D, mass, mass, stiffness, damping, l0);
        links.planePosition[id] = position;
        links.axis[id] = axis;
        return id;
    }

    /** Adds an inverse-square attractor: force {@code -attraction / d^2} while d exceeds {@code limit}. */
    public int addAttractor(int massA, int massB, double limit, double attraction) {
        int id = addLink(LinkKind.ATTRACTOR3D, massA, massB, 0, 0, limit);
        links.attraction[id] = attraction;
        return id;
    }

    /**
     * Adds a contact group: a Contact3D between every unordered pair of the given masses (i before j in
     * the given order), found each step by a broad phase (a neighbour list with a skin distance, built on
     * a hashed grid) instead of N² explicit links.
     *
     * @param massIds the members, each a live mass, no duplicates
     * @param threshold contact distance (the pair interacts while closer than this), &gt; 0
     * @return the group id
     */
    public int addContactGroup(int[] massIds, double threshold, double stiffness, double damping) {
        for (int id : massIds) {
            checkMass(id);
        }
        groups.add(new ContactGroupSpec(massIds.clone(), threshold, stiffness, damping));
        markTopology();
        return groups.size() - 1;
    }

    /** Replaces the members of a contact group. */
    public void setContactGroupMembers(int group, int[] massIds) {
        ContactGroupSpec g = group(group);
        for (int id : massIds) {
            checkMass(id);
        }
        g.members = massIds.clone();
        markTopology();
    }

    /** Sets the threshold, stiffness and damping of a contact group. */
    public void setContactGroupParams(int group, double threshold, double stiffness, double damping) {
        ContactGroupSpec g = group(group);
        g.threshold = threshold;
        g.stiffness = stiffness;
        g.damping = damping;
        markTopology();
    }

    /** @return {threshold, stiffness, damping} of a contact group, per step. */
    public double[] contactGroupParams(int group) {
        ContactGroupSpec g = group(group);
        return new double[] {g.threshold, g.stiffness, g.damping};
    }

    /** Removes a contact group. */
    public void removeContactGroup(int group) {
        group(group).alive = false;
        markTopology();
    }

    /** @return the number of times the neighbour lists of all contact groups have been rebuilt (for tests). */
    long contactGroupRebuilds() {
        compile();
        long n = 0;
        for (ContactGroupKernel g : plan.groups) {
            n += g.rebuilds();
        }
        return n;
    }

    private ContactGroupSpec group(int gid) {
        if (gid < 0 || gid >= groups.size() || !groups.get(gid).alive) {
            throw new IllegalArgumentException("no live contact group with id " + gid);
        }
        return groups.get(gid);
    }

    /**
     * The live links attached to a mass, in id order. The first call after links or masses were added indexes
     * them all, in O(masses + links); later calls cost the mass's own links.
     */
    public int[] linksOf(int mass) {
        checkMass(mass);
        indexIncidence();
        int n = 0;
        for (int i = incidenceStart[mass]; i < incidenceStart[mass + 1]; i++) {
            n += links.alive[incidence[i]] ? 1 : 0;
        }
        int[] out = new int[n];
        n = 0;
        for (int i = incidenceStart[mass]; i < incidenceStart[mass + 1]; i++) {
            if (links.alive[incidence[i]]) {
                out[n++] = incidence[i];
            }
        }
        return out;
    }

    /** How many times the mass-to-links index was built (for the cost tests). */
    public long incidenceBuilds() {
        return incidenceBuilds;
    }

    /** How many step plans were compiled (for the cost tests). */
    public long compiles() {
        return compiles;
    }

    /** Indexes the links of each mass (ids in order, dead ones included) if links or masses were added since. */
    private void indexIncidence() {
        int nl = links.count;
        int nm = masses.count;
        if (nl == incidenceLinks && nm == incidenceMasses) {
            return;
        }
        int[] start = new int[nm + 1];
        for (int l = 0; l < nl; l++) {
            start[links.a[l] + 1]++;
            if (links.b[l] != links.a[l]) {
                start[links.b[l] + 1]++;
            }
        }
        for (int m = 0; m < nm; m++) {
            start[m + 1] += start[m];
        }
        int[] at = new int[start[nm]];
        int[] next = Arrays.copyOf(start, nm);
        for (int l = 0; l < nl; l++) {
            at[next[links.a[l]]++] = l;
            if (links.b[l] != links.a[l]) {
                at[next[links.b[l]]++] = l;
            }
        }
        incidenceStart = start;
        incidence = at;
        incidenceLinks = nl;
        incidenceMasses = nm;
        incidenceBuilds++;
    }

    /** Removes one link. */
    public void removeLink(int id) {
        checkLink(id);
        links.alive[id] = false;
        markTopology();
    }

    /** Removes a mass and every link attached to it, in time proportional to its links (see {@link #linksOf}). */
    public void removeMass(int id) {
        checkMass(id);
        indexIncidence();
        for (int i = incidenceStart[id]; i < incidenceStart[id + 1]; i++) {
            links.alive[incidence[i]] = false;
        }
        masses.alive[id] = false;
        if (id == divergedMass) {
            forgetDivergence();
        }
        markTopology();
    }

    /**
     * Puts a free mass under velocity control: from the next step it moves by exactly (vx, vy, vz) per step and
     * ignores forces, friction and gravity. A Mass2DPlane keeps its z, a Mass1D its x and y. Calling it again
     * changes the velocity without recompiling.
     *
     * @param vx displacement per step along x (units per step)
     */
    public void driveVelocity(int id, double vx, double vy, double vz) {
        checkMass(id);
        MassKind own = masses.userKind(id);
        if (!own.isDrivable()) {
            throw new IllegalArgumentException("a " + own.label() + " cannot be put under velocity control");
        }
        int q = 3 * id;
        masses.drive[q] = own == MassKind.MASS1D ? 0 : vx;
        masses.drive[q + 1] = own == MassKind.MASS1D ? 0 : vy;
        masses.drive[q + 2] = own == MassKind.MASS2D_PLANE ? 0 : vz;
        if (masses.drivenFrom[id] == null) {
            masses.drivenFrom[id] = own;
            masses.kind[id] = MassKind.DRIVEN3D;
            markTopology();
        } else {
            refreshMass(id);
        }
    }

    /** Ends the velocity control of a mass; it keeps the velocity it had and feels forces again. */
    public void stopDriving(int id) {
        checkMass(id);
        if (masses.drivenFrom[id] != null) {
            masses.kind[id] = masses.drivenFrom[id];
            masses.drivenFrom[id] = null;
            markTopology();
        }
    }

    /** @return true while a mass is under velocity control. */
    public boolean isDriven(int id) {
        checkMass(id);
        return masses.drivenFrom[id] != null;
    }

    /** Turns a mass into a fixed point (Ground3D) at its current position; its links stay attached. */
    public void makeFixed(int id) {
        checkMass(id);
        double[] pos = scratchA;
        position(id, pos);
        masses.drivenFrom[id] = null;
        masses.kind[id] = MassKind.GROUND3D;
        setPosition(id, pos[0], pos[1], pos[2]);
        markTopology();
    }

    /** Removes every mass, link and contact group, and forgets a divergence. Ids already issued stay invalid. */
    public void clear() {
        forgetDivergence();
        for (int id = 0; id < masses.count; id++) {
            masses.alive[id] = false;
        }
        for (int id = 0; id < links.count; id++) {
            links.alive[id] = false;
        }
        for (ContactGroupSpec g : groups) {
            g.alive = false;
        }
        markTopology();
    }

    // ------------------------------------------------------------------ compiling and stepping

    /**
     * Chooses whether dense blocks of spring-family links (chains, mesh rows and columns) are stepped as
     * vectorisable stencil runs (the default; with {@link #setStencilSweeps sweeps} off only for models of up to
     * 16,384 masses, or any size when several threads step it, since larger single-threaded ones stream from
     * memory, where index arrays are then faster) or all through index arrays. Both give the same physics; the
     * force sums on a mass are added in a different order, so results differ by round-off only.
     */
    public void setStencilRuns(boolean enabled) {
        if (enabled != stencils) {
            stencils = enabled;
            markTopology();
        }
    }

    /**
     * Chooses how stencil runs are stepped. Enabled (the default): each run in one sweep over its memory per
     * step, and a run of offset 1 (a chain, the rows of a mesh) whose masses are all of one kind moves those
     * masses itself, block by block just ahead of its links, instead of leaving them to their own kernel.
     * Disabled: as before sweeps existed, every mass kernel first, then each run in two passes (near ends,
     * then far ends); kept to compare the two (benchmarks, tests). Both give the same physics: a mass whose
     * forces all come from its run's links (the inside of a chain) gets the same bits either way, others may
     * differ by round-off (forces from several kernels are summed in another order). Enabled, SpringDamper1D
     * links that form a chain in batch order also run as one loop per chain (bit-identical to one by one).
     */
    public void setStencilSweeps(boolean enabled) {
        if (enabled != sweeps) {
            sweeps = enabled;
            markTopology(); // the size limit of runs depends on it: recompile (state is carried over)
        }
    }

    /**
     * Stencil runs stepped in one sweep pay off at every size (measured: a 367 x 367 sheet 0.80x the time of
     * index arrays, 150 x 150 0.99x). In the two-pass form they pay off while the model is cache-resident, and
     * always when several threads step it (only runs split across threads; index-array links run on one thread).
     */
    private boolean useStencils() {
        if (!stencils) {
            return false;
        }
        int live = 0;
        for (int id = 0; id < masses.count; id++) {
            if (masses.alive[id]) {
                live++;
            }
        }
        return sweeps || live <= StencilPlanner.MAX_MASSES || (stepper != null && live >= parallelMinElements / 3);
    }

    /** @return the number of stencil runs in the compiled plan (0 when the scene has no dense link block). */
    public int stencilRunCount() {
        compile();
        int n = 0;
        for (LinkBatch b : plan.batches) {
            if (b != null) {
                n += b.runs.length;
            }
        }
        return n;
    }

    /** Compiles the scene now if its topology or effects changed since the last compile. */
    public void compile() {
        if (topologyDirty && plan != null && holdTopology) {
            if (effectsDirty) {
                plan.sweepRuns = sweeps;
                plan.selectKernels();
                effectsDirty = false;
            }
        } else if (topologyDirty || plan == null) {
            compiles++;
            plan = PlanCompiler.compile(masses, links, medium, plan, useStencils(), sweeps, groups);
            topologyDirty = false;
            effectsDirty = false;
        } else if (effectsDirty) {
            plan.sweepRuns = sweeps;
            plan.selectKernels();
            effectsDirty = false;
        }
    }

    private void markTopology() {
        topologyDirty = true;
        topologyVersion++;
    }

    /**
     * Defers topology compiles until {@link #install}: from now on {@link #compile()} (and stepping) keeps the
     * current plan when only the topology changed. Call it on the stepping thread before a structural change whose
     * plan another thread will prepare ({@link #prepareCompile()}).
     */
    public void holdTopology() {
        holdTopology = true;
    }

    /** @return true between {@link #holdTopology()} and {@link #install}: topology changes wait for the install. */
    public boolean isHoldingTopology() {
        return holdTopology;
    }

    /**
     * Builds, on the calling thread, the plan a compile would make from the tables as they are now, without
     * touching the tables or the current plan, so that the stepping thread may go on stepping meanwhile. Nothing
     * else may change the topology until {@link #install}; if something does, the install compiles in full.
     *
     * @return the prepared plan, or null when there is nothing to compile (or the tables changed under it)
     */
    public PreparedPlan prepareCompile() {
        if (!topologyDirty || plan == null) {
            return null;
        }
        long version = topologyVersion;
        StepPlan from = plan;
        try {
            return new PreparedPlan(PlanCompiler.prepare(masses, links, medium, useStencils(), sweeps, groups), from,
                    version);
        } catch (RuntimeException raced) {
            return null; // a topology change on the stepping thread raced the preparation: install compiles in full
        }
    }

    /**
     * Ends a {@link #holdTopology() hold} on the stepping thread, between two steps: swaps in the prepared plan,
     * copying the live state of the masses and links it carries over from the current plan and writing every
     * coefficient from the current parameters (O(masses + links), no allocation), with the same result, bit for
     * bit, as a compile here. A missing or outdated prepared plan is replaced by a full compile.
     *
     * @param prepared the plan from {@link #prepareCompile()}, or null
     * @return true when the prepared plan was installed
     */
    public boolean install(PreparedPlan prepared) {
        holdTopology = false;
        boolean used = false;
        if (prepared != null && topologyDirty && prepared.from == plan && prepared.version == topologyVersion) {
            plan = PlanCompiler.install(masses, links, medium, plan, prepared.prepared);
            plan.sweepRuns = sweeps;
            plan.selectKernels(); // the medium's effects may have changed since the preparation
            topologyDirty = false;
            effectsDirty = false;
            installs++;
            used = true;
        }
        if (plan != null && (topologyDirty || effectsDirty)) {
            compile(); // not prepared (or raced): compile here, as before; a model never compiled waits for its step
        }
        return used;
    }

    /** @return how many prepared plans {@link #install} has swapped in so far (for tests and measurements). */
    public long preparedInstalls() {
        return installs;
    }

    /** A step plan built off the stepping thread by {@link #prepareCompile()}, to be swapped in by {@link #install}. */
    public static final class PreparedPlan {
        private final PlanCompiler.Prepared prepared;
        private final StepPlan from;
        private final long version;

        private PreparedPlan(PlanCompiler.Prepared prepared, StepPlan from, long version) {
            this.prepared = prepared;
            this.from = from;
            this.version = version;
        }
    }

    /** @return true when the next step will compile the plan first (the topology or an effect changed). */
    boolean needsCompile() {
        return plan == null || topologyDirty || effectsDirty;
    }

    /**
     * @return the plan for a stability analysis: the same as {@link #planForReading()}
     */
    public StepPlan planForAnalysis() {
        return planForReading();
    }

    /**
     * @return the plan for a query that only reads it (energies, stability analysis, effect labels): the current
     *     plan, as it is. A pending kernel re-selection (an effect switched on or off) does not change the state or
     *     the coefficients, so it is left to the stepping thread, as is a topology change that is held (a plan being
     *     prepared beside the live one): a query running on another thread while a realtime owner steps never
     *     touches the plan the owner is stepping. Compiles only when there is no plan yet or the topology changed
     *     without a hold, which happens only before the first step or in locked mode, where the caller is the only
     *     thread using the engine.
     */
    public StepPlan planForReading() {
        if (plan == null || (topologyDirty && !holdTopology)) {
            compile();
        }
        return plan;
    }

    /**
     * @return the plan being stepped, as it is, or null before the first compile: never compiles, for a reader on
     *     another thread than the realtime owner (which alone may compile while it steps)
     */
    public StepPlan livePlan() {
        return plan;
    }

    /**
     * @return the simple class names of the kernels one step runs, in order, as {@link StepPlan#kernelNames()};
     *     read-only: when a compile or a kernel re-selection is pending, the names come from a plan prepared for
     *     the occasion (as {@link #prepareCompile()} does), never from re-selecting the live plan's kernels
     */
    public String[] kernelNames() {
        if (plan != null && !needsCompile()) {
            return plan.kernelNames();
        }
        if (plan == null) {
            compile(); // never compiled: nobody steps it yet, so this is what the first step would do
            return plan.kernelNames();
        }
        try {
            return PlanCompiler.prepare(masses, links, medium, useStencils(), sweeps, groups).plan.kernelNames();
        } catch (RuntimeException raced) {
            return plan.kernelNames(); // the stepping thread changed the topology meanwhile: the plan it steps
        }
    }

    /** @return the current compiled plan, compiling first if needed. */
    public StepPlan plan() {
        compile();
        return plan;
    }

    /** Runs one simulation step (nothing if the engine has diverged). */
    public void step() {
        step(1);
    }

    /**
     * Runs {@code n} simulation steps. The divergence guard scans the state every
     * {@link DivergenceGuard#interval()} steps; when it finds a diverged mass the engine stops at that
     * step, records the mass ({@link #divergedMass()}) and runs no further step until
     * {@link #clearDivergence()}.
     *
     * @return the number of steps actually run
     */
    public int step(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("step count must be >= 0, got " + n);
        }
        if (divergedMass >= 0 || n == 0) {
            return 0;
        }
        if (topologyDirty || effectsDirty) {
            compile();
        }
        StepPlan p = plan;
        if (stepper != null && n > 1 && p.elementCount() >= parallelMinElements) {
            return stepChoosingMode(p, n);
        }
        return stepOnOneThread(p, n);
    }

    /**
     * Runs {@code n} steps on one thread, as {@link #step(int)} does, and records after each step one coordinate of
     * each of {@code count} masses: {@code out[offset + s * count + i]} is coordinate {@code axes[i]} (0 x, 1 y, 2 z)
     * of mass {@code ids[i]} after step s (0 for the first). The steps are bit-identical to {@link #step(int)}'s.
     * A block of audio is computed this way: the positions are read from the plan's arrays, with no call per read.
     *
     * @return the number of steps actually run (fewer than n when the divergence guard stopped them); the step
     *     that diverged is recorded too
     */
    public int stepRecording(int n, int[] ids, int[] axes, int count, double[] out, int offset) {
        if (n < 0) {
            throw new IllegalArgumentException("step count must be >= 0, got " + n);
        }
        for (int i = 0; i < count; i++) {
            checkMass(ids[i]);
            if (axes[i] < 0 || axes[i] > 2) {
                throw new IllegalArgumentException("axis must be 0, 1 or 2, got " + axes[i]);
            }
        }
        if (divergedMass >= 0 || n == 0) {
            return 0;
        }
        if (topologyDirty || effectsDirty) {
            compile();
        }
        StepPlan p = plan;
        if (recordSlots.length < count) {
            recordSlots = new int[Math.max(count, 2 * recordSlots.length)];   // only when more points are listened to
        }
        int[] slots = recordSlots;
        for (int i = 0; i < count; i++) {
            slots[i] = masses.slot[ids[i]];
        }
        return stepOnOneThread(p, n, slots, axes, count, out, offset);
    }

    /**
     * Runs n steps of a plan big enough for the parallel stepper, in the mode the chooser finds faster (a probe
     * step in a mode, then the rest of the batch in the faster one).
     */
    private int stepChoosingMode(StepPlan p, int n) {
        int ran = 0;
        while (ran < n && divergedMass < 0) {
            boolean parallel = modes.parallelNext();
            int chunk = modes.probing() ? 1 : n - ran;
            long t0 = modes.now();
            int r = parallel ? stepInParallel(p, chunk) : stepOnOneThread(p, chunk);
            modes.record(parallel, r, modes.now() - t0);
            ran += r;
            if (r < chunk) {
                break;   // the divergence guard stopped the batch
            }
        }
        return ran;
    }

    private int stepInParallel(StepPlan p, int n) {
        hookPlan = p;
        hookSteps = 0;
        p.prepareStep();
        try {
            return stepper.run(p, n, guardHook);
        } finally {
            steps += hookSteps;
            hookPlan = null;
        }
    }

    /** Times the choice between one thread and the parallel stepper with this clock from now on (for tests). */
    void setModeClock(java.util.function.LongSupplier nanoClock) {
        modes = new StepModeChooser(nanoClock);
    }

    /** Steps run on all threads, and on one thread for a plan big enough for them (for tests). */
    long[] stepsByMode() {
        return new long[] {modes.parallelSteps(), modes.serialSteps()};
    }

    private int stepOnOneThread(StepPlan p, int n) {
        return stepOnOneThread(p, n, null, null, 0, null, 0);
    }

    /**
     * Runs n steps on the calling thread; after each, records coordinate {@code axes[i]} of plan slot
     * {@code slots[i]} into {@code out[offset + s * count + i]} for i &lt; count (none when count is 0).
     */
    private int stepOnOneThread(StepPlan p, int n, int[] slots, int[] axes, int count, double[] out, int offset) {
        double[] single = count == 1 ? (axes[0] == 0 ? p.x : axes[0] == 1 ? p.y : p.z) : null;
        int singleSlot = count == 1 ? slots[0] : -1;
        int ran = 0;
        try {
            while (ran < n) {
                p.step();
                if (count == 1) {
                    out[offset + ran] = single[singleSlot];
                } else if (count > 1) {
                    int q = offset + ran * count;
                    for (int i = 0; i < count; i++) {
                        int a = axes[i];
                        out[q + i] = (a == 0 ? p.x : a == 1 ? p.y : p.z)[slots[i]];
                    }
                }
                ran++;
                if (guardAfterStep(p, steps + ran)) {
                    break;
                }
            }
        } finally {
            steps += ran;
        }
        return ran;
    }

    /** The divergence check after one parallel step; runs on the stepping thread while the others wait. */
    private boolean afterParallelStep() {
        hookSteps++;
        return guardAfterStep(hookPlan, steps + hookSteps);
    }

    /**
     * Counts one step down to the next divergence scan and, when it is due, scans the plan.
     *
     * @param stepNumber the step count just reached, recorded if the scan finds a diverged mass
     * @return true when the plan has diverged and stepping must stop
     */
    private boolean guardAfterStep(StepPlan p, long stepNumber) {
        if (--countdown != 0) {
            return false;
        }
        countdown = guard.interval();
        int bad = guard.scan(p);
        if (bad < 0) {
            return false;
        }
        divergedMass = p.massId[bad];
        divergedAt = stepNumber;
        return true;
    }

    /**
     * Sets how many threads may step large models (1, the default, is single-threaded). With more, a model
     * of at least {@link #parallelThreshold()} elements is stepped in parallel when {@link #step(int)} runs
     * more than one step; results are bit-identical to single-threaded stepping (tested with batch sizes
     * 1 to 5 and 2 to 4 threads). Threads beyond the number of cores only slow things down. The worker
     * threads are daemon threads; {@link #close()} stops them, and they are stopped as well once the engine
     * has become unreachable.
     */
    public void setThreads(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("thread count must be >= 1, got " + threads);
        }
        if (stepper != null) {
            if (stepper.threads() == threads) {
                return;
            }
            closeStepper();
        }
        if (threads > 1) {
            ParallelStepper s = new ParallelStepper(threads);
            stepper = s;
            stepperCleanup = CLEANER.register(this, s::close);
        }
        markTopology();
    }

    /**
     * Stops the worker threads of parallel stepping and releases them; idempotent. The engine stays usable
     * and steps on the calling thread from then on ({@link #threads()} is 1) until {@link #setThreads} asks
     * for more threads again.
     */
    @Override
    public void close() {
        if (stepper != null) {
            closeStepper();
            markTopology();
        }
    }

    private void closeStepper() {
        stepperCleanup.clean();
        stepperCleanup = null;
        stepper = null;
    }

    /** @return the worker threads of the parallel stepper (empty when stepping on one thread), for tests. */
    Thread[] stepperThreads() {
        return stepper == null ? new Thread[0] : stepper.workers();
    }

    /** @return the number of threads that may step large models. */
    public int threads() {
        return stepper == null ? 1 : stepper.threads();
    }

    /** Sets the smallest model (masses plus links) stepped in parallel; smaller ones cannot pay the barriers. */
    public void setParallelThreshold(int elements) {
        if (elements < 0) {
            throw new IllegalArgumentException("parallel threshold must be >= 0 elements, got " + elements);
        }
        parallelMinElements = elements;
    }

    /** @return the smallest model stepped in parallel, in elements. */
    public int parallelThreshold() {
        return parallelMinElements;
    }

    /** @return the divergence guard, to tune its interval and limit. */
    public DivergenceGuard guard() {
        return guard;
    }

    /** Scans the state now (outside the regular interval) and records a divergence if there is one. */
    public boolean checkNow() {
        compile();
        int bad = guard.scan(plan);
        if (bad >= 0 && divergedMass < 0) {
            divergedMass = plan.massId[bad];
            divergedAt = steps;
        }
        return divergedMass >= 0;
    }

    /** @return the id of the mass found diverged, or -1 while the state is sane. */
    public int divergedMass() {
        return divergedMass;
    }

    /** @return the step count at which the divergence was detected, or -1. */
    public long divergedAt() {
        return divergedAt;
    }

    /**
     * Lets the engine step again after a divergence. Repair the positions and parameters first; this clears
     * every pending force (they were computed from the diverged state) and makes every link forget its
     * previous distance, so the next step starts from the repaired positions at rest.
     */
    public void clearDivergence() {
        forgetDivergence();
        if (plan != null) {
            StepPlan p = plan;
            java.util.Arrays.fill(p.fx, 0.0);
            java.util.Arrays.fill(p.fy, 0.0);
            java.util.Arrays.fill(p.fz, 0.0);
            PlanCompiler.resetLinkHistory(p, -1);
        }
    }

    /**
     * Lets stepping resume without touching the state: used when the diverged mass is removed or the model
     * cleared, so that no dead id stays recorded. A state that is still diverged is found again by the next
     * scan.
     */
    private void forgetDivergence() {
        divergedMass = -1;
        divergedAt = -1;
        countdown = guard.interval();
    }

    /** Sets the number of steps between two divergence scans; the next scan comes at most that many steps away. */
    public void setDivergenceCheckInterval(int steps) {
        guard.setInterval(steps);
        countdown = Math.min(countdown, steps);
    }

    /**
     * @return how many times a link's length or plane position was set since this engine was created (a reader that
     *     copies them skips the copy while this count stays)
     */
    public long linkParameterEdits() {
        return linkParameterEdits;
    }

    /** @return the number of steps run since this engine was created. */
    public long stepCount() {
        return steps;
    }

    // ------------------------------------------------------------------ introspection

    /** @return true when {@code id} names a live mass. */
    public boolean isMass(int id) {
        return masses.isLive(id);
    }

    /** @return true when {@code id} names a live link. */
    public boolean isLink(int id) {
        return links.isLive(id);
    }

    /** @return the kind of a live mass. */
    public MassKind massKind(int id) {
        checkMass(id);
        return masses.userKind(id);
    }

    /** @return the kind of a live link. */
    public LinkKind linkKind(int id) {
        checkLink(id);
        return links.kind[id];
    }

    /** @return the id of the first mass of a link. */
    public int linkMassA(int id) {
        checkLink(id);
        return links.a[id];
    }

    /** @return the id of the second mass of a link (the same as the first for a plane contact). */
    public int linkMassB(int id) {
        checkLink(id);
        return links.b[id];
    }

    /** @return the number of link ids issued so far, live or not. */
    public int linkIdCount() {
        return links.count;
    }

    // ------------------------------------------------------------------ parameters

    /** @return the inertia M of a mass. */
    public double mass(int id) {
        checkMass(id);
        return masses.mass[id];
    }

    /** Sets the inertia M of a mass (must be finite and positive; the caller validates). */
    public void setMass(int id, double m) {
        checkMass(id);
        masses.mass[id] = m;
        refreshMass(id);
    }

    /** @return the internal stiffness of an oscillator, per step. */
    public double oscStiffness(int id) {
        checkMass(id);
        return masses.stiffness[id];
    }

    /** @return the internal damping of an oscillator, per step. */
    public double oscDamping(int id) {
        checkMass(id);
        return masses.damping[id];
    }

    /** @return the stiffness K of a link, per step. */
    public double linkStiffness(int id) {
        checkLink(id);
        return links.stiffness[id];
    }

    /** @return the damping Z of a link, per step. */
    public double linkDamping(int id) {
        checkLink(id);
        return links.damping[id];
    }

    /** @return the length parameter of a link (rest length, threshold, radius, offset or limit). */
    public double linkLength(int id) {
        checkLink(id);
        return links.length[id];
    }

    /** @return the rest position of an oscillator (or the position of a fixed point) along axis 0, 1 or 2. */
    public double restPosition(int id, int axis) {
        checkMass(id);
        return masses.rest[3 * id + axis];
    }

    /** @return the plane coordinate of a plane contact, in units (the plane lies across its axis there). */
    public double planePosition(int id) {
        checkLink(id, LinkKind.PLANE_CONTACT3D);
        return links.planePosition[id];
    }

    /** @return the attraction factor A of an attractor (force {@code -A / d^2}), per-step force units times d^2. */
    public double attraction(int id) {
        checkLink(id, LinkKind.ATTRACTOR3D);
        return links.attraction[id];
    }

    /** @return the axis (0, 1, 2) of a plane contact. */
    public int linkAxis(int id) {
        checkLink(id);
        return links.axis[id];
    }

    /** Sets the stiffness, damping and length of a link together. */
    public void setLinkParams(int id, double stiffness, double damping, double length) {
        checkLink(id);
        links.stiffness[id] = stiffness;
        links.damping[id] = damping;
        links.length[id] = length;
        linkParameterEdits++;
        refreshLink(id);
    }

    /** Sets the plane coordinate of a plane contact. */
    public void setPlanePosition(int id, double position) {
        checkLink(id, LinkKind.PLANE_CONTACT3D);
        links.planePosition[id] = position;
        linkParameterEdits++;
        refreshLink(id);
    }

    /** Sets the attraction factor A of an attractor. */
    public void setAttraction(int id, double attraction) {
        checkLink(id, LinkKind.ATTRACTOR3D);
        links.attraction[id] = attraction;
        refreshLink(id);
    }

    /**
     * @return parameter {@code i} beyond stiffness, damping and length of a link whose kind has it
     *     ({@link LinkKind#auxNames()}), per step
     */
    public double linkAux(int id, int i) {
        checkAux(id, i);
        return i == 0 ? links.aux0[id] : links.aux1[id];
    }

    /** Sets parameter {@code i} beyond stiffness, damping and length of a link whose kind has it, per step. */
    public void setLinkAux(int id, int i, double value) {
        checkAux(id, i);
        if (i == 0) {
            links.aux0[id] = value;
        } else {
            links.aux1[id] = value;
        }
        linkParameterEdits++;
        refreshLink(id);
    }

    private void checkAux(int id, int i) {
        checkLink(id);
        if (i < 0 || i >= links.kind[id].auxCount()) {
            throw new IllegalArgumentException("link " + id + " is a " + links.kind[id].label() + ", which has no"
                    + " parameter " + i + " beyond K, Z and its length");
        }
    }

    // ------------------------------------------------------------------ state

    /** Writes the position of a mass into {@code out[0..2]}. */
    public void position(int id, double[] out) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            out[0] = plan.x[s];
            out[1] = plan.y[s];
            out[2] = plan.z[s];
        } else {
            int q = 6 * id;
            out[0] = masses.pending[q];
            out[1] = masses.pending[q + 1];
            out[2] = masses.pending[q + 2];
        }
    }

    /**
     * Copies the positions of {@code n} masses into {@code out}: mass {@code ids[i]} to {@code out[3i..3i+2]} (a
     * reader's bulk query; the ids must be live, which the caller checked when it collected them).
     */
    public void copyPositions(int[] ids, int n, double[] out) {
        StepPlan p = plan;
        int[] slots = masses.slot;
        double[] pending = masses.pending;
        for (int i = 0; i < n; i++) {
            int id = ids[i];
            int s = p == null ? -1 : slots[id];
            int q = 3 * i;
            if (s >= 0) {
                out[q] = p.x[s];
                out[q + 1] = p.y[s];
                out[q + 2] = p.z[s];
            } else {
                int r = 6 * id;
                out[q] = pending[r];
                out[q + 1] = pending[r + 1];
                out[q + 2] = pending[r + 2];
            }
        }
    }

    /** Writes the displacement of a mass over the last step, X(n) - X(n-1), into {@code out[0..2]}. */
    public void displacement(int id, double[] out) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            out[0] = plan.x[s] - plan.px[s];
            out[1] = plan.y[s] - plan.py[s];
            out[2] = plan.z[s] - plan.pz[s];
        } else {
            int q = 6 * id;
            out[0] = masses.pending[q] - masses.pending[q + 3];
            out[1] = masses.pending[q + 1] - masses.pending[q + 4];
            out[2] = masses.pending[q + 2] - masses.pending[q + 5];
        }
    }

    /** Writes the force accumulated on a mass for its next step into {@code out[0..2]}. */
    public void force(int id, double[] out) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            out[0] = plan.fx[s];
            out[1] = plan.fy[s];
            out[2] = plan.fz[s];
        } else {
            int q = 3 * id;
            out[0] = masses.pendingForce[q];
            out[1] = masses.pendingForce[q + 1];
            out[2] = masses.pendingForce[q + 2];
        }
    }

    /**
     * Moves a mass to a position and sets its velocity to zero (both current and previous positions); its links
     * forget the distance they saw before.
     */
    public void setPosition(int id, double x, double y, double z) {
        setState(id, x, y, z, x, y, z);
    }

    /**
     * Moves a mass to a position with zero velocity as the paper's engine did: its links keep the distance they
     * saw at their last step, so each damper takes the jump for a radial velocity in the next step.
     */
    public void setPositionKeepingLinkHistory(int id, double x, double y, double z) {
        writeState(id, x, y, z, x, y, z, false);
    }

    /** Sets the current and previous positions of a mass; its links forget the distance they saw before. */
    public void setState(int id, double x, double y, double z, double prevX, double prevY, double prevZ) {
        writeState(id, x, y, z, prevX, prevY, prevZ, true);
    }

    private void writeState(int id, double x, double y, double z, double prevX, double prevY, double prevZ,
                            boolean resetLinks) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            plan.x[s] = x;
            plan.y[s] = y;
            plan.z[s] = z;
            plan.px[s] = prevX;
            plan.py[s] = prevY;
            plan.pz[s] = prevZ;
            plan.tx[s] = x;
            plan.ty[s] = y;
            plan.tz[s] = z;
        } else {
            masses.setPending(id, x, y, z, prevX, prevY, prevZ);
            masses.pendingTarget[3 * id] = Double.NaN;
        }
        if (s >= 0 && resetLinks) {
            PlanCompiler.resetLinkHistory(plan, s);
        }
        if (masses.kind[id].isFixed()) {
            masses.setRest(id, x, y, z);
            refreshMass(id);
        }
    }

    /**
     * Adds a force to a mass's buffer; it acts once, in the next step. Never compiles: a mass added since the
     * last compile keeps the force in a pending buffer that the next compile moves into the plan.
     */
    public void addForce(int id, double fx, double fy, double fz) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            plan.fx[s] += fx;
            plan.fy[s] += fy;
            plan.fz[s] += fz;
            if ((fx != 0 || fy != 0) && plan.isOneDimensional(s)) {
                plan.offAxisResidue = true;   // no kernel may clear it: cleared before the next step
            }
        } else {
            int q = 3 * id;
            masses.pendingForce[q] += fx;
            masses.pendingForce[q + 1] += fy;
            masses.pendingForce[q + 2] += fz;
        }
    }

    /**
     * Sets the target position that an input module (haptic avatar or position driver) follows. Never
     * compiles: the target of a mass added since the last compile is kept until the next compile.
     */
    public void setInputTarget(int id, double x, double y, double z) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            plan.tx[s] = x;
            plan.ty[s] = y;
            plan.tz[s] = z;
        } else {
            int q = 3 * id;
            masses.pendingTarget[q] = x;
            masses.pendingTarget[q + 1] = y;
            masses.pendingTarget[q + 2] = z;
        }
    }

    /**
     * Copies the force accumulated on a mass since the last call into {@code out[0..2]} and clears it. Never
     * compiles and allocates nothing.
     *
     * @return the number of steps over which the force was accumulated
     */
    public long takeForce(int id, double[] out) {
        checkMass(id);
        int s = liveSlot(id);
        if (s >= 0) {
            out[0] = plan.fx[s];
            out[1] = plan.fy[s];
            out[2] = plan.fz[s];
            plan.fx[s] = 0;
            plan.fy[s] = 0;
            plan.fz[s] = 0;
        } else {
            double[] f = masses.pendingForce;
            int q = 3 * id;
            out[0] = f[q];
            out[1] = f[q + 1];
            out[2] = f[q + 2];
            f[q] = 0;
            f[q + 1] = 0;
            f[q + 2] = 0;
        }
        long n = steps - masses.lastTake[id];
        masses.lastTake[id] = steps;
        int q = 3 * id;
        masses.lastTaken[q] = out[0];
        masses.lastTaken[q + 1] = out[1];
        masses.lastTaken[q + 2] = out[2];
        masses.lastTakenSteps[id] = n;
        return n;
    }

    /**
     * Writes the sum that {@link #takeForce} last took from a mass into {@code out[0..2]} (a reader's query: a
     * snapshot taken just after a take shows it).
     *
     * @return the number of steps that sum covered; 0 when nothing was taken yet (out is then untouched)
     */
    public long lastTakenForce(int id, double[] out) {
        checkMass(id);
        long n = masses.lastTakenSteps[id];
        if (n > 0) {
            int q = 3 * id;
            out[0] = masses.lastTaken[q];
            out[1] = masses.lastTaken[q + 1];
            out[2] = masses.lastTaken[q + 2];
        }
        return n;
    }

    /** @return the number of steps over which a mass's force buffer has summed since {@link #takeForce} last read it. */
    public long stepsSinceTake(int id) {
        checkMass(id);
        return steps - masses.lastTake[id];
    }

    /** @return the current distance between the two masses of a link (the axis gap for a plane contact). */
    public double linkDistance(int id) {
        checkLink(id);
        int a = links.a[id];
        if (links.kind[id] == LinkKind.PLANE_CONTACT3D) {
            return coordinate(a, links.axis[id]) - links.planePosition[id];
        }
        int b = links.b[id];
        if (links.kind[id].isOneDimensional()) {
            return coordinate(a, 2) - coordinate(b, 2);
        }
        double dx = coordinate(a, 0) - coordinate(b, 0);
        double dy = coordinate(a, 1) - coordinate(b, 1);
        double dz = coordinate(a, 2) - coordinate(b, 2);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** @return one coordinate (axis 0, 1 or 2) of a live mass's position, written nowhere (a reader's query). */
    private double coordinate(int id, int axis) {
        int s = liveSlot(id);
        if (s >= 0) {
            return axis == 0 ? plan.x[s] : axis == 1 ? plan.y[s] : plan.z[s];
        }
        return masses.pending[6 * id + axis];
    }

    /**
     * Re-expresses the state for a new step duration: with {@code ratio = oldRate / newRate}, every
     * displacement per step (velocity) is multiplied by {@code ratio} and every pending or accumulated force
     * by {@code ratio^2}, keeping positions, so velocities in units per second and forces in newtons are kept.
     */
    public void rescaleTime(double ratio) {
        compile();
        StepPlan p = plan;
        double r2 = ratio * ratio;
        for (int s = 0; s < p.nMass; s++) {
            p.fx[s] *= r2;
            p.fy[s] *= r2;
            p.fz[s] *= r2;
            p.px[s] = p.x[s] - (p.x[s] - p.px[s]) * ratio;
            p.py[s] = p.y[s] - (p.y[s] - p.py[s]) * ratio;
            p.pz[s] = p.z[s] - (p.z[s] - p.pz[s]) * ratio;
        }
        for (LinkBatch b : p.batches) {
            if (b == null) {
                continue;
            }
            for (int j = 0; j < b.n; j++) {
                boolean tracked = b.kind.isOneDimensional() || b.prev(j) >= 0;
                if (tracked && b.kind.keepsHistory()) {
                    double d = PlanCompiler.distanceOf(b, j, p);
                    b.setPrev(j, d - (d - b.prev(j)) * ratio);
                }
            }
        }
    }

    // ------------------------------------------------------------------ helpers

    private int liveSlot(int id) {
        return plan == null ? -1 : masses.slot[id];
    }

    private void refreshMass(int id) {
        int s = liveSlot(id);
        if (s >= 0) {
            PlanCompiler.fillMass(plan, s, masses, id, medium);
        }
    }

    private void refreshLink(int id) {
        if (plan != null && links.slot[id] >= 0) {
            PlanCompiler.fillLink(plan.batches[links.kind[id].ordinal()], links.slot[id], links, id);
        }
    }

    private void checkMass(int id) {
        if (!masses.isLive(id)) {
            throw new IllegalArgumentException("no live mass with id " + id);
        }
    }

    private void checkLink(int id) {
        if (!links.isLive(id)) {
            throw new IllegalArgumentException("no live link with id " + id);
        }
    }

    private void checkLink(int id, LinkKind kind) {
        checkLink(id);
        if (links.kind[id] != kind) {
            throw new IllegalArgumentException("link " + id + " is a " + links.kind[id].label() + ", not a "
                    + kind.label());
        }
    }
}
