/*
 * A test fixture in the style of the paper's audio-haptic sketches (our own code): a PhyUGen subclass builds its
 * model in its constructor and steps it in its own uGenerate under a sketch-level lock, a 1 kHz "haptic" thread
 * moves the avatar and reads its force under the same lock, and draw() reads positions under it too. Only the
 * imports are Tactus's. At frame 150 it prints what it heard, for RealtimePaperSketchTest.
 */

import ddf.minim.*;
import ddf.minim.ugens.*;
import tactus.*;
import tactus.audio.*;

Minim minim;
AudioOutput out;
Gain gain;
PhyString simUGen;
final Object lock = new Object();
volatile float peak = 0;
volatile long hapticReads = 0;
volatile double forceSum = 0;

public class PhyString extends PhyUGen {
  private float prevIn = 0, prevOut = 0;

  public PhyString(int sampleRate) {
    super(sampleRate);
    mdl = new PhysicalModel(sampleRate, 60);
    mdl.setGravity(0);
    mdl.setFriction(0);
    mdl.addHapticInput3D("hapticMass", new Vect3D(0, -1, 0), 30);
    mdl.addGround3D("gL", new Vect3D(0, 0, 0));
    for (int i = 0; i < 60; i++) {
      mdl.addMass2DPlane("str" + i, 1, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
    }
    mdl.addGround3D("gR", new Vect3D(0.1 * 61, 0, 0));
    mdl.addSpringDamper3D("sp", 0.05, 0.2, 0.0001, "gL", "str0");
    for (int i = 0; i < 59; i++) {
      mdl.addSpringDamper3D("sp", 0.05, 0.2, 0.0001, "str" + i, "str" + (i + 1));
    }
    mdl.addSpringDamper3D("sp", 0.05, 0.2, 0.0001, "str59", "gR");
    for (int i = 0; i < 60; i++) {
      mdl.addContact3D("col", 0.05, 0.1, 0.001, "hapticMass", "str" + i);
    }
    mdl.init();
  }

  @Override
  protected void sampleRateChanged() {
    mdl.setSimRate((int) sampleRate());
  }

  @Override
  protected void uGenerate(float[] channels) {
    float sample;
    synchronized (lock) {
      mdl.computeStep();
      float x = (float) (mdl.getMatPosition("str20").y * 2);
      sample = x - prevIn + 0.95 * prevOut;   // the paper's DC blocker
      prevIn = x;
      prevOut = sample;
    }
    if (abs(sample) > peak) {
      peak = abs(sample);
    }
    java.util.Arrays.fill(channels, sample);
  }
}

void setup() {
  size(400, 200);
  minim = new Minim(this);
  simUGen = new PhyString(44100);
  out = minim.getLineOut();
  gain = new Gain(0);
  simUGen.patch(gain).patch(out);
  thread("hapticLoop");
}

void hapticLoop() {
  // stands in for the Haply thread: sweeps the avatar up and down through the string at 1 kHz
  long t = 0;
  while (true) {
    double y = 0.5 * Math.sin(t * 2 * Math.PI / 700.0);
    synchronized (lock) {
      simUGen.getModel().setHapticPosition("hapticMass", new Vect3D(2.05, y, 0));
      Vect3D f = simUGen.getModel().getHapticForce("hapticMass");
      forceSum += Math.abs(f.y);
    }
    hapticReads++;
    t++;
    delay(1);
  }
}

void draw() {
  background(0);
  stroke(255);
  synchronized (lock) {
    for (int i = 0; i < 60; i++) {
      Vect3D p = simUGen.getModel().getMatPosition("str" + i);
      point(20 + (float) p.x * 58, height / 2 + (float) p.y * 100);
    }
  }
  if (frameCount == 150) {
    println("paper-sketch: steps=" + simUGen.getModel().getStepCount() + " peak=" + peak + " hapticReads="
        + hapticReads + " forceSum=" + forceSum);
  }
}
