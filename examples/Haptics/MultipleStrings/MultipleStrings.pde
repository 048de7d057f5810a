/*
 * MultipleStrings: five strings tuned to a pentatonic scale, one below the other, played with one plectrum
 * through a Haply: pluck them one at a time, or sweep across all of them for a strum. Each string is the
 * plucked string of the paper (Mass2DPlane masses, spring-dampers, a contact with the plectrum for every
 * mass), all five in one model stepped at 44.1 kHz by a PhyUGen, each heard from its own place in stereo.
 * With no Haply plugged in, an emulated one is used and the mouse is the hand (the screen says so); until the
 * mouse moves, the emulated hand tours the workspace on its own and strums the strings it crosses.
 *
 * Threads: as in PluckedString, the PhyUGen steps the model on the audio thread and the HapticSession's 1 kHz
 * loop (AUDIO mode) talks to it through an AvatarExchange: the handle's position goes in, the summed force on
 * the plectrum comes back with the number of audio steps it covers, and the loop renders its mean per step.
 */

import tactus.*;
import tactus.audio.*;
import tactus.haptics.*;
import ddf.minim.*;

// ---- the strings (algorithmic units: per audio step)
int strings = 5;
int masses = 30;                 // moving masses per string
float spacing = 0.1;             // distance between neighbours at rest
float restLength = 0.05;         // shorter than the spacing: the strings are taut
float baseStiffness = 0.2;       // the lowest string's link stiffness
float[] ratio = {1, 9.0 / 8, 5.0 / 4, 3.0 / 2, 5.0 / 3};  // pitch of each string against the lowest
float gap = 0.3;                 // distance between strings
float damping = 0.0001;
float sphere = 0.08;             // the plectrum's sphere of action
float contactK = 0.01;
float contactZ = 0.001;
float volume = 20;               // listening gain of each string

// ---- device mapping: model = (-alpha x + ox, alpha y + oy) for the handle at (x, y) metres
float alpha = 25;
float beta = 1500;
float stringLength = (masses + 1) * spacing;
float ox, oy;                    // set in setup(): the middle string's middle is the middle of the workspace

// ---- screen
float zoom = 260;
float left, top;

PhysicalModel mdl;
PhyUGen ugen;
ListeningPoint[] ears = new ListeningPoint[strings];
AvatarExchange exchange;
Minim minim;
AudioOutput out;
HapticSession haptics;
HapticLoop loop;
ModelRenderer renderer;
double[] force = new double[2];
double[] handle = new double[2];

String massName(int s, int i) {
  if (i == 0 || i == masses + 1) {
    return "s" + s + "_end" + i;
  }
  return "s" + s + "_m" + i;
}

float stringY(int s) {
  return (s - (strings - 1) / 2.0) * gap;
}

void setup() {
  size(900, 520);
  frameRate(60);
  left = (width - zoom * stringLength) / 2;
  top = 290;

  mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0);
  mdl.setFriction(0.00001);
  mdl.addHapticInput3D("plectrum", new Vect3D(stringLength / 2, -1, 0), 40);
  for (int s = 0; s < strings; s++) {
    // The pitch of a taut chain goes with the square root of its stiffness.
    float k = baseStiffness * ratio[s] * ratio[s];
    float y = stringY(s);
    mdl.addGround3D(massName(s, 0), new Vect3D(0, y, 0));
    for (int i = 1; i <= masses; i++) {
      mdl.addMass2DPlane(massName(s, i), 1, new Vect3D(i * spacing, y, 0), new Vect3D());
      mdl.addContact3D("pick_" + s + "_" + i, sphere, contactK, contactZ, "plectrum", massName(s, i));
    }
    mdl.addGround3D(massName(s, masses + 1), new Vect3D(stringLength, y, 0));
    for (int i = 0; i <= masses; i++) {
      mdl.addSpringDamper3D("link_" + s + "_" + i, restLength, k, damping, massName(s, i), massName(s, i + 1));
    }
  }
  mdl.init();

  // Audio: one listening point per string (mass 3, y displacement from its rest), spread from left to right.
  ugen = new PhyUGen(mdl);
  for (int s = 0; s < strings; s++) {
    ears[s] = ugen.listenToMass(massName(s, 3), SteppedModel.Y, volume, -0.8 + 1.6 * s / (strings - 1));
  }
  exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);   // the loop takes the mean per step itself
  ugen.attachAvatar("plectrum", exchange);
  minim = new Minim(this);
  out = LineOut.open(minim);      // a silent real-time output when there is no sound card
  strum(0.03);                    // strum once, so that you hear at once that the sound works
  ugen.patch(out);

  // Haptics: the first Haply found, or the emulator with the mouse as the hand (other hardware:
  // HapticSession.open(this, HaplyPreset.TWO_DIY_V3)). The session closes the board when the sketch ends.
  haptics = HapticSession.open(this);
  double[] box = new double[4];
  haptics.deviceWorkspace(box);                     // metres
  ox = (float) (stringLength / 2 + alpha * 0.5 * (box[0] + box[1]));
  oy = (float) (-alpha * 0.5 * (box[2] + box[3]));
  loop = haptics.attach(new ExchangeAvatarLink(exchange));  // position to the audio thread, force back
  loop.setMode(HapticLoop.Mode.AUDIO);
  loop.setPositionGain(alpha);
  loop.setForceGain(beta);
  loop.setOrigin(ox, oy, 0);
  loop.start();
  haptics.setView(zoom, left, top);                 // how the model is drawn: the mouse lands on the plectrum

  renderer = new ModelRenderer(this);
  renderer.setScale(zoom);
  renderer.setSize(matModuleType.Mass2DPlane, 0.01);
  renderer.setScaling(matModuleType.Mass2DPlane, 0);
  renderer.setColor(matModuleType.Mass2DPlane, 250, 210, 120);
  renderer.setSize(matModuleType.Ground3D, 0.02);
  renderer.setScaling(matModuleType.Ground3D, 0);
  renderer.setSize(matModuleType.HapticInput3D, sphere);
  renderer.setScaling(matModuleType.HapticInput3D, 0);
  renderer.setColor(matModuleType.HapticInput3D, 230, 60, 60);
  renderer.setColor(linkModuleType.SpringDamper3D, 90, 200, 230, 255);
}

void draw() {
  background(20, 24, 32);
  pushMatrix();
  translate(left, top);
  renderer.renderModel(mdl);
  loop.devicePosition(handle);
  loop.deviceForce(force);
  float hx = (float) (-alpha * handle[0] + ox) * zoom;
  float hy = (float) (alpha * handle[1] + oy) * zoom;
  noFill();
  stroke(255);
  strokeWeight(1.5);
  ellipse(hx, hy, 10, 10);
  stroke(255, 230, 90);
  strokeWeight(3);
  line(hx, hy, hx - (float) force[0] * 60, hy + (float) force[1] * 60);
  popMatrix();

  fill(220);
  textSize(14);
  text("Pluck one string, or sweep the plectrum (red) across all five to strum them.", 16, 24);
  text("[ and ]: sphere of action (" + nf(sphere, 1, 2) + ")   UP / DOWN: volume (" + nf(volume, 1, 0)
    + ")   SPACE: strum for you   R: still the strings", 16, 44);
  text(String.format("force on the handle %.2f N", Math.hypot(force[0], force[1])), 16, height - 34);
  haptics.drawStatus();   // which board, or that the mouse is the hand (and why the loop stopped, if it did)
}

// Lifts every string into a triangle of the given height, its apex a quarter of the way along, and lets go.
void strum(float height) {
  int at = masses / 4;
  for (int s = 0; s < strings; s++) {
    for (int i = 1; i <= masses; i++) {
      float y = i <= at ? height * i / at : height * (masses + 1 - i) / (masses + 1 - at);
      mdl.setMatPosition(massName(s, i), new Vect3D(i * spacing, stringY(s) + y, 0));
    }
  }
}

void keyPressed() {
  if (key == '[' || key == ']') {
    sphere = constrain(sphere + (key == ']' ? 0.01 : -0.01), 0.02, 0.14);
    mdl.setLinkParamsForName("pick_", contactK, contactZ, sphere);
    renderer.setSize(matModuleType.HapticInput3D, sphere);
  } else if (key == ' ') {
    strum(0.03);
  } else if (key == 'r' || key == 'R') {
    strum(0);
  } else if (keyCode == UP || keyCode == DOWN) {
    volume = constrain(volume * (keyCode == UP ? 1.25 : 0.8), 1, 300);
    for (ListeningPoint ear : ears) {
      ear.setGain(volume);
    }
  }
}
