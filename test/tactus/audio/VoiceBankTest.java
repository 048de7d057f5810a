package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * {@link VoiceBank}: voices of one shape in one model. Each voice moves as the same voice alone in its own model,
 * bit for bit, and rings at the frequency the discrete string's theory gives for its own stiffness; notes take the
 * voices in turn; one PhyUGen hears every voice; a builder that breaks the rules leaves the model as it was.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class VoiceBankTest {
    private static final int MASSES = 12;
    /** Stiffness of voice v's springs per step squared (M = 1): voice v rings about (1 + v / 2) times voice 0. */
    private static double stiffness(int voice) {
        double r = 1 + voice / 2.0;
        return 0.01 * r * r;
    }

    /**
     * One voice: a 1-D string of {@link #MASSES} Mass1D between two Ground1D, undamped, its masses displaced along z
     * in the shape of the first mode, sin(pi i / (n + 1)) times amplitude (0: at rest).
     */
    private static VoiceBank.VoiceBuilder string(double amplitude) {
        return (m, p, v) -> {
            m.addGround1D(p + "g0", new Vect3D(0, 0, 0));
            for (int i = 1; i <= MASSES; i++) {
                double z = amplitude * Math.sin(Math.PI * i / (MASSES + 1));
                m.addMass1D(p + "m" + i, 1, new Vect3D(i, 0, z), new Vect3D());
            }
            m.addGround1D(p + "g1", new Vect3D(MASSES + 1, 0, 0));
            for (int i = 0; i <= MASSES; i++) {
                String a = i == 0 ? "g0" : "m" + i;
                String b = i == MASSES ? "g1" : "m" + (i + 1);
                m.addSpringDamper1D(p + "s" + i, 0, stiffness(v), 0, p + a, p + b);
            }
        };
    }

    private static PhysicalModel bank(int voices, VoiceBank.VoiceBuilder b, VoiceBank[] out) {
        PhysicalModel m = new PhysicalModel(44100);
        out[0] = new VoiceBank(m, voices, b);
        m.init();
        return m;
    }

    /** @return voice v of {@link #string}(0) alone in its own model: a one-voice bank told it is voice v (names v0_) */
    private static PhysicalModel alone(int voice) {
        PhysicalModel m = new PhysicalModel(44100);
        VoiceBank.VoiceBuilder b = string(0);
        new VoiceBank(m, 1, (mm, p, ignored) -> b.build(mm, p, voice));
        m.init();
        return m;
    }

    @Test
    void eachVoiceMovesAsItsStringAloneBitForBitAndTheOthersStayAtRest() {
        for (int voices : new int[] {1, 3, 8}) {
            VoiceBank[] bank = new VoiceBank[1];
            PhysicalModel m = bank(voices, string(0), bank);
            int played = voices - 1;
            PhysicalModel alone = alone(played);
            m.triggerForceImpulse(bank[0].name(played, "m4"), 0, 0, 0.3);
            alone.triggerForceImpulse("v0_m4", 0, 0, 0.3);
            for (int step = 0; step < 3000; step += 500) {
                m.computeNSteps(500);
                alone.computeNSteps(500);
                for (int i = 1; i <= MASSES; i++) {
                    assertEquals(alone.getMatPosition("v0_m" + i).z, m.getMatPosition(bank[0].name(played, "m" + i)).z,
                            0.0, voices + " voices, mass m" + i + " after " + (step + 500) + " steps");
                    for (int v = 0; v < played; v++) {
                        assertEquals(0.0, m.getMatPosition(bank[0].name(v, "m" + i)).z, 0.0,
                                "voice " + v + " was not played and must stay at rest");
                    }
                }
            }
            assertTrue(Math.abs(m.getMatPosition(bank[0].name(played, "m4")).z) > 1e-4, "the played voice moves");
        }
    }

    @Test
    void everyVoiceRingsAtTheDiscreteStringsFirstModeForItsOwnStiffness() {
        int voices = 4;
        VoiceBank[] bank = new VoiceBank[1];
        PhysicalModel m = bank(voices, string(0.01), bank);
        int steps = 20_000;
        int[] crossings = new int[voices];
        int[] first = new int[voices];
        int[] last = new int[voices];
        double[] before = new double[voices];
        for (int v = 0; v < voices; v++) {
            before[v] = m.getMatPosition(bank[0].name(v, "m6")).z;
            first[v] = -1;
        }
        for (int s = 1; s <= steps; s++) {
            m.computeStep();
            for (int v = 0; v < voices; v++) {
                double z = m.getMatPosition(bank[0].name(v, "m6")).z;
                if (before[v] > 0 && z <= 0) {   // a downward zero crossing: one per period
                    if (first[v] < 0) {
                        first[v] = s;
                    } else {
                        crossings[v]++;
                        last[v] = s;
                    }
                }
                before[v] = z;
            }
        }
        for (int v = 0; v < voices; v++) {
            // 2 - 2 cos(W) = 4 (K / M) sin^2(pi / (2 (n + 1))): radians per step of the first mode
            double w = 2 * Math.asin(Math.sqrt(stiffness(v)) * Math.sin(Math.PI / (2 * (MASSES + 1))));
            double expectedPeriod = 2 * Math.PI / w;
            double measured = (last[v] - first[v]) / (double) crossings[v];
            assertTrue(crossings[v] >= 20, "voice " + v + " rang " + crossings[v] + " periods");
            assertEquals(expectedPeriod, measured, expectedPeriod * 0.005,
                    "voice " + v + ": period in steps, theory against the model");
        }
    }

    @Test
    void notesTakeTheVoicesInTurnAndMoveOnlyTheVoiceTheyPlay() {
        VoiceBank[] bank = new VoiceBank[1];
        PhysicalModel m = bank(3, string(0), bank);
        int[] played = new int[5];
        for (int i = 0; i < 5; i++) {
            played[i] = bank[0].triggerForceImpulse("m3", 0, 0, 0.2);
            m.computeStep();
            for (int v = i + 1; v < 3; v++) {   // the voices no note has taken yet
                assertEquals(0.0, m.getMatPosition(bank[0].name(v, "m3")).z, 0.0,
                        "voice " + v + " is not played yet after note " + i);
            }
            assertTrue(m.getMatPosition(bank[0].name(played[i], "m3")).z != 0, "note " + i + " moves its voice");
        }
        assertArrayEquals(new int[] {0, 1, 2, 0, 1}, played);
    }

    @Test
    void onePhyUGenHearsEveryVoiceAsTheSumOfTheVoicesAlone() {
        int voices = 3;
        VoiceBank[] bank = new VoiceBank[1];
        PhysicalModel m = bank(voices, string(0), bank);
        PhyUGen u = new PhyUGen(m);
        ListeningPoint[] points = bank[0].listenToMass(u, "m5", SteppedModel.Z, 100, 0.8);
        assertEquals(voices, points.length);
        assertEquals(voices, u.listeningPoints().length);
        assertEquals(-0.8, points[0].pan(), 1e-12);
        assertEquals(0.0, points[1].pan(), 1e-12);
        assertEquals(0.8, points[2].pan(), 1e-12);
        m.triggerForceImpulse(bank[0].name(0, "m2"), 0, 0, 0.2);
        m.triggerForceImpulse(bank[0].name(2, "m7"), 0, 0, -0.1);
        PhyUGen[] alone = new PhyUGen[2];
        int[] voice = {0, 2};
        String[] struck = {"m2", "m7"};
        double[] force = {0.2, -0.1};
        for (int k = 0; k < 2; k++) {
            PhysicalModel a = alone(voice[k]);
            a.triggerForceImpulse("v0_" + struck[k], 0, 0, force[k]);
            alone[k] = new PhyUGen(a);
            alone[k].listenToMass("v0_m5", SteppedModel.Z, 100, 0);
        }
        float[] frame = new float[1];
        float[] one = new float[1];
        double peak = 0;
        for (int s = 0; s < 4096; s++) {
            u.tick(frame);
            double sum = 0;
            for (PhyUGen a : alone) {
                a.tick(one);
                sum += one[0];
            }
            peak = Math.max(peak, Math.abs(sum));
            assertEquals(sum, frame[0], 1e-6 + 1e-5 * Math.abs(sum), "sample " + s);
        }
        assertTrue(peak > 1e-3, "the voices are heard (peak " + peak + ")");
    }

    @Test
    void aBuilderThatBreaksTheRulesLeavesTheModelAsItWas() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround1D("floor", new Vect3D());
        m.addMass1D("bead", 1, new Vect3D(0, 0, 1), new Vect3D());
        m.addSpringDamper1D("hold", 0, 0.1, 0, "floor", "bead");
        VoiceBank.VoiceBuilder good = string(0);
        IllegalArgumentException noPrefix = assertThrows(IllegalArgumentException.class,
                () -> new VoiceBank(m, 2, (mm, p, v) -> {
                    good.build(mm, p, v);
                    mm.addMass1D("loose" + v, 1, new Vect3D(), new Vect3D());
                }));
        assertTrue(noPrefix.getMessage().contains("\"loose0\""), noPrefix.getMessage());
        assertUnchanged(m);
        IllegalArgumentException shape = assertThrows(IllegalArgumentException.class,
                () -> new VoiceBank(m, 3, (mm, p, v) -> {
                    good.build(mm, p, v);
                    if (v == 2) {
                        mm.addMass1D(p + "extra", 1, new Vect3D(), new Vect3D());
                    }
                }));
        assertTrue(shape.getMessage().contains("voice 2"), shape.getMessage());
        assertUnchanged(m);
        IllegalArgumentException names = assertThrows(IllegalArgumentException.class,
                () -> new VoiceBank(m, 2, (mm, p, v) -> {
                    mm.addMass1D(p + (v == 0 ? "a" : "b"), 1, new Vect3D(), new Vect3D());
                }));
        assertTrue(names.getMessage().contains("\"v1_b\"") && names.getMessage().contains("\"v0_a\""),
                names.getMessage());
        assertUnchanged(m);
        IllegalStateException thrown = assertThrows(IllegalStateException.class,
                () -> new VoiceBank(m, 4, (mm, p, v) -> {
                    good.build(mm, p, v);
                    if (v == 3) {
                        throw new IllegalStateException("builder failed");
                    }
                }));
        assertEquals("builder failed", thrown.getMessage());
        assertUnchanged(m);
        assertThrows(IllegalArgumentException.class, () -> new VoiceBank(m, 2, (mm, p, v) -> { }));
        assertThrows(IllegalArgumentException.class, () -> new VoiceBank(m, 0, good));
        assertThrows(IllegalArgumentException.class, () -> new VoiceBank(m, VoiceBank.MAX_VOICES + 1, good));
        assertUnchanged(m);
        // the model still works and takes a bank
        VoiceBank bank = new VoiceBank(m, 2, good);
        assertEquals(2 + 2 * (MASSES + 2), m.getNumberOfMats());
        assertEquals("v1_m3", bank.name(1, "m3"));
        assertThrows(IllegalArgumentException.class, () -> bank.name(2, "m3"));
    }

    @Test
    void listeningChecksItsArgumentsBeforeAddingAnything() {
        VoiceBank[] bank = new VoiceBank[1];
        PhysicalModel m = bank(2, string(0), bank);
        PhyUGen other = new PhyUGen(new PhysicalModel(44100));
        assertThrows(IllegalArgumentException.class,
                () -> bank[0].listenToMass(other, "m1", SteppedModel.Z, 1, 0));
        PhyUGen u = new PhyUGen(m);
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> bank[0].listenToMass(u, "v0_m1", SteppedModel.Z, 1, 0));
        assertTrue(missing.getMessage().contains("without the voice prefix"), missing.getMessage());
        assertThrows(IllegalArgumentException.class, () -> bank[0].listenToMass(u, "m1", 3, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> bank[0].listenToMass(u, "m1", SteppedModel.Z, 1, 1.5));
        assertEquals(0, u.listeningPoints().length);
    }

    private static void assertUnchanged(PhysicalModel m) {
        assertEquals(2, m.getNumberOfMats(), "masses after a failed build");
        assertEquals(1, m.getNumberOfLinks(), "interactions after a failed build");
        assertEquals("floor", m.getMatNameAt(0));
        assertEquals("bead", m.getMatNameAt(1));
        assertEquals("hold", m.getLinkNameAt(0));
    }
}
