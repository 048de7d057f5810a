package tactus.audio;

import java.util.concurrent.atomic.AtomicInteger;

import tactus.PhysicalModel;

/**
 * A bank of voices of one shape (a polyphonic instrument) built side by side in one {@link PhysicalModel} and heard
 * through one {@link PhyUGen}. Each voice is a copy of the modules a {@link VoiceBuilder} adds, named with the voice's
 * prefix ({@code "v0_"}, {@code "v1_"}, ...); a voice is played by name ({@link #name}) or by taking the next voice in
 * turn ({@link #nextVoice}, {@link #triggerForceImpulse}).
 *
 * <p>Why one model: the model steps every voice in one call per sample, its mass kernels run over the masses of all
 * voices in one loop, and one PhyUGen reads every voice, so Minim ticks one unit generator instead of one per voice.
 * Sixteen 30-mass strings cost about two thirds of the time of sixteen models, each with its own PhyUGen
 * (docs/audio.md, "Polyphony").
 */
public final class VoiceBank {

    /** Adds the modules of one voice to a model. */
    @FunctionalInterface
    public interface VoiceBuilder {
        /**
         * Adds one voice's masses and interactions to the model, each named {@code prefix + name}; every voice must
         * add the same module types under the same names, in the same order. The voice index lets voices differ in
         * their parameters (a harp's strings), not in their shape.
         *
         * @param model the model the bank is built in
         * @param prefix the voice's prefix, {@code "v" + voice + "_"}
         * @param voice the voice's index, from 0
         */
        void build(PhysicalModel model, String prefix, int voice);
    }

    /** The most voices one bank holds. */
    public static final int MAX_VOICES = 1024;

    private final PhysicalModel model;
    private final int voices;
    private final AtomicInteger turn = new AtomicInteger();

    /**
     * Builds a bank of voices in a model: calls the builder once per voice and checks that every voice added the same
     * modules, under its own prefix. Call {@code model.init()} afterwards, as after any building.
     *
     * @param model the model to build the voices in
     * @param voices the number of voices, 1 to {@value #MAX_VOICES}
     * @param builder adds one voice's modules
     * @throws IllegalArgumentException naming the voice and the module when a voice adds a module without its prefix,
     *     adds nothing, or differs in shape from voice 0; the modules the bank added are then removed again, and the
     *     model is as it was. An exception the builder throws is passed on after the same clean-up.
     */
    public VoiceBank(PhysicalModel model, int voices, VoiceBuilder builder) {
        if (model == null || builder == null) {
            throw new IllegalArgumentException("VoiceBank: the model and the builder must not be null");
        }
        if (voices < 1 || voices > MAX_VOICES) {
            throw new IllegalArgumentException("VoiceBank: voices must be between 1 and " + MAX_VOICES + ", got "
                    + voices);
        }
        this.model = model;
        this.voices = voices;
        int masses0 = model.getNumberOfMats();
        int links0 = model.getNumberOfLinks();
        try {
            for (int v = 0; v < voices; v++) {
                int masses = model.getNumberOfMats();
                int links = model.getNumberOfLinks();
                builder.build(model, prefix(v), v);
                checkVoice(v, masses, links, masses0, links0);
            }
        } catch (RuntimeException | Error e) {
            removeFrom(masses0, links0);
            throw e;
        }
    }

    /**
     * Checks that voice v added at least one mass, only names with its prefix, and the shape of voice 0 (which starts
     * at masses0 and links0).
     */
    private void checkVoice(int v, int masses, int links, int masses0, int links0) {
        int addedMasses = model.getNumberOfMats() - masses;
        int addedLinks = model.getNumberOfLinks() - links;
        String p = prefix(v);
        if (addedMasses == 0) {
            throw new IllegalArgumentException("VoiceBank: voice " + v + " added no mass; the builder must add the"
                    + " voice's masses (named \"" + p + "...\") to the model it is given");
        }
        for (int i = masses; i < masses + addedMasses; i++) {
            checkPrefix(v, "mass", model.getMatNameAt(i));
        }
        for (int i = links; i < links + addedLinks; i++) {
            checkPrefix(v, "interaction", model.getLinkNameAt(i));
        }
        if (v == 0) {
            return;
        }
        int perVoiceMasses = (masses - masses0) / v;
        int perVoiceLinks = (links - links0) / v;
        if (addedMasses != perVoiceMasses || addedLinks != perVoiceLinks) {
            throw new IllegalArgumentException("VoiceBank: voice " + v + " added " + addedMasses + " masses and "
                    + addedLinks + " interactions, voice 0 " + perVoiceMasses + " and " + perVoiceLinks
                    + "; every voice must have the same shape (vary parameters with the voice index, not modules)");
        }
        for (int i = 0; i < addedMasses; i++) {
            sameModule(v, "mass", model.getMatNameAt(masses0 + i), model.getMatNameAt(masses + i),
                    model.getMatTypeAt(masses0 + i), model.getMatTypeAt(masses + i));
        }
        for (int i = 0; i < addedLinks; i++) {
            sameModule(v, "interaction", model.getLinkNameAt(links0 + i), model.getLinkNameAt(links + i),
                    model.getLinkTypeAt(links0 + i), model.getLinkTypeAt(links + i));
        }
    }

    private static void checkPrefix(int v, String kind, String name) {
        if (!name.startsWith(prefix(v))) {
            throw new IllegalArgumentException("VoiceBank: voice " + v + " added the " + kind + " \"" + name
                    + "\" without its prefix; name every module of the voice prefix + name (here \"" + prefix(v)
                    + name + "\")");
        }
    }

    /** Checks that module i of voice v is named and typed as module i of voice 0. */
    private static void sameModule(int v, String kind, String first, String here, Object firstType, Object type) {
        String a = first.substring(prefix(0).length());
        String b = here.substring(prefix(v).length());
        if (!a.equals(b) || !firstType.equals(type)) {
            throw new IllegalArgumentException("VoiceBank: voice " + v + " added the " + kind + " \"" + here + "\" ("
                    + type + ") where voice 0 added \"" + first + "\" (" + firstType + "); every voice must add the"
                    + " same module types under the same names, in the same order");
        }
    }

    /** Removes every interaction, then every mass, added after the given counts (the bank's own, on error). */
    private void removeFrom(int masses0, int links0) {
        for (int i = model.getNumberOfLinks() - 1; i >= links0; i--) {
            model.removeLink(i);
        }
        for (int i = model.getNumberOfMats() - 1; i >= masses0; i--) {
            model.removeMatAndConnectedLinks(i);
        }
    }

    /** {@return the prefix of a voice's module names: {@code "v" + voice + "_"}} */
    public static String prefix(int voice) {
        return "v" + voice + "_";
    }

    /** {@return the model the voices are built in} */
    public PhysicalModel getModel() {
        return model;
    }

    /** {@return the number of voices} */
    public int size() {
        return voices;
    }

    /**
     * {@return the name of a voice's copy of a module (or of a subset its builder created):
     * {@code prefix(voice) + name}}
     *
     * @throws IllegalArgumentException naming the voice when it is not between 0 and size() - 1
     */
    public String name(int voice, String name) {
        checkVoiceIndex(voice);
        return prefix(voice) + name;
    }

    private void checkVoiceIndex(int voice) {
        if (voice < 0 || voice >= voices) {
            throw new IllegalArgumentException("VoiceBank: voice must be between 0 and " + (voices - 1) + ", got "
                    + voice);
        }
    }

    /**
     * Takes the next voice in turn, the one taken longest ago (round robin), for a new note. A voice still ringing is
     * played again: the new excitation adds to its motion. Safe from any thread.
     *
     * @return the voice's index, 0 to size() - 1
     */
    public int nextVoice() {
        return Math.floorMod(turn.getAndIncrement(), voices);
    }

    /**
     * Plays a note: takes the {@linkplain #nextVoice next voice} and adds a force to its copy of a mass for the next
     * step only, as {@link PhysicalModel#triggerForceImpulse(String, double, double, double)} does (REAL_UNITS: N).
     *
     * @param mass the mass's name within a voice (without prefix)
     * @return the voice played
     */
    public int triggerForceImpulse(String mass, double fx, double fy, double fz) {
        int v = nextVoice();
        model.triggerForceImpulse(prefix(v) + mass, fx, fy, fz);
        return v;
    }

    /**
     * Listens to every voice's copy of a mass through one PhyUGen: one listening point per voice, the voices spread
     * evenly across the stereo field from -spread (voice 0) to +spread (the last voice).
     *
     * @param ugen a PhyUGen of this bank's model
     * @param mass the mass's name within a voice (without prefix)
     * @param axis {@link SteppedModel#X}, {@link SteppedModel#Y} or {@link SteppedModel#Z}
     * @param gain output units per model unit, for each voice
     * @param spread 0 (every voice in the centre) to 1 (from hard left to hard right)
     * @return the listening points, one per voice, in voice order
     * @throws IllegalArgumentException when the PhyUGen plays another model or spread is outside 0..1; nothing is
     *     added then
     */
    public ListeningPoint[] listenToMass(PhyUGen ugen, String mass, int axis, double gain, double spread) {
        if (ugen == null || ugen.getModel() != model) {
            throw new IllegalArgumentException("VoiceBank.listenToMass: the PhyUGen must play this bank's model (make"
                    + " it with new PhyUGen(bank.getModel()))");
        }
        if (axis < SteppedModel.X || axis > SteppedModel.Z) {
            throw new IllegalArgumentException("VoiceBank.listenToMass: axis must be SteppedModel.X, Y or Z (0, 1, 2),"
                    + " got " + axis);
        }
        if (!(spread >= 0 && spread <= 1)) {
            throw new IllegalArgumentException("VoiceBank.listenToMass: spread must be between 0 and 1, got " + spread);
        }
        if (!model.matExists(prefix(0) + mass)) {
            throw new IllegalArgumentException("VoiceBank.listenToMass: no mass \"" + mass + "\" in voice 0 (looked for \""
                    + prefix(0) + mass + "\"); give the name without the voice prefix");
        }
        ListeningPoint[] points = new ListeningPoint[voices];
        for (int v = 0; v < voices; v++) {
            double pan = voices == 1 ? 0 : spread * (2.0 * v / (voices - 1) - 1);
            points[v] = ugen.listenToMass(prefix(v) + mass, axis, gain, pan);
        }
        return points;
    }
}
