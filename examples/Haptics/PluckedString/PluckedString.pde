/*
 * PluckedString: the audio-haptic plucked string of the paper. The string sounds at 44.1 kHz (the model is
 * stepped once per audio sample inside a PhyUGen) while a 1 kHz haptic loop lets you feel it through a Haply:
 * the plectrum touches every mass of the string within its sphere of action, so you can pluck anywhere, hold
 * it on the string to palm-mute, or touch lightly at a node (a third or a quarter of the way) for a harmonic.
 * With no Haply plugged in, an emulated one is used and the mouse is the hand (the screen says so); until the
 * mouse moves, the emulated hand tours the workspace on its own and plucks the string as it crosses it.
 *
 * Threads: the PhyUGen steps the model on the audio thread; the HapticSession's 1 kHz loop (AUDIO mode) hands
 * it the handle's position and takes back the force on the plectrum through an AvatarExchange, which pairs the
 * summed force with the number of audio steps it covers under one lock-free sequence lock, so the loop renders
 * the exact mean force per audio step (held between Minim's bursts of steps), with beta newtons per model force
 * unit. ExchangeAvatarLink is the only glue, and the loop calls it directly since it never waits (attaching the
 * session to the model's avatar, haptics.attach(mdl, "plectrum"), also works, through a helper thread).
 */

import tactus.*;
import tactus.audio.*;
import tactus.haptics.*;
import ddf.minim.*;

// ---- the string (algorithmic units: per audio step)
int masses = 30;          // moving masses of the string
float spacing = 0.1;      // distance between neighbours at rest
float restLength = 0.05;  // length parameter of the links: shorter than the spacing, so the string is taut
float stiffness = 0.2;    // link stiffness
float damping = 0.0001;   // link damping
float sphere = 0.08;      // the plectrum's sphere of action (contact distance)
float contactK = 0.01;    // contact stiffness
float contactZ = 0.001;   // contact damping
float volume = 30;        // listening gain

// ---- device mapping: model = (-alpha x + ox, alpha y + oy) for the handle at (x, y) metres
float alpha = 25;         // model units per metre
float beta = 1500;        // newtons per model force unit (the force is averaged over the audio steps)
float stringLength = (masses + 1) * spacing;
float ox, oy;             // set in setup(): the middle of the string is the middle of the device's workspace

// ---- screen: pixels per model unit and where the model's origin is drawn
float zoom = 260;
float left, top;

PhysicalModel mdl;
PhyUGen string;
ListeningPoint ear;
AvatarExchange exchange;
Minim minim;
AudioOutput out;
HapticSession haptics;
HapticLoop loop;
ModelRenderer renderer;
double[] force = new double[2];
double[] handle = new double[2];
long lastTicks;
int lastMillis;
float loopRate;

void setup() {
  size(900, 500);
  frameRate(60);
  left = (width - zoom * stringLength) / 2;
  top = 300;

  // The model: a string of Mass2DPlane masses between two fixed points, and the plectrum.
  mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0);
  mdl.setFriction(0.00001);
  mdl.addGround3D("g0", new Vect3D(0, 0, 0));
  for (int i = 1; i <= masses; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(i * spacing, 0, 0), new Vect3D());
  }
  mdl.addGround3D("g" + (masses + 1), new Vect3D(stringLength, 0, 0));
  for (int i = 0; i <= masses; i++) {
    String a = i == 0 ? "g0" : "m" + i;
    String b = i == masses ? "g" + (masses + 1) : "m" + (i + 1);
    mdl.addSpringDamper3D("s" + i, restLength, stiffness, damping, a, b);
  }
  mdl.addHapticInput3D("plectrum", new Vect3D(stringLength / 2, -0.5, 0), 40);
  for (int i = 1; i <= masses; i++) {
    mdl.addContact3D("pick" + i, sphere, contactK, contactZ, "plectrum", "m" + i);
  }
  mdl.init();

  // Audio: the PhyUGen steps the model at the output's rate and listens to mass 3 (y displacement).
  string = new PhyUGen(mdl);
  ear = string.listenToMass("m3", SteppedModel.Y, volume, 0);
  exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);   // the loop takes the mean per step itself
  string.attachAvatar("plectrum", exchange);
  minim = new Minim(this);
  out = LineOut.open(minim);      // a silent real-time output when there is no sound card
  pluck(masses / 4, 0.03);        // pluck it once, so that you hear at once that the sound works
  string.patch(out);

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
  renderer.setSize(matModuleType.Mass2DPlane, 0.012);
  renderer.setScaling(matModuleType.Mass2DPlane, 0);
  renderer.setColor(matModuleType.Mass2DPlane, 250, 210, 120);
  renderer.setSize(matModuleType.Ground3D, 0.025);
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

  // The handle (white ring) and the force it receives (yellow arrow, 60 px per newton).
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

  if (millis() - lastMillis >= 500) {
    long t = loop.ticks();
    loopRate = (t - lastTicks) * 1000.0 / max(1, millis() - lastMillis);
    lastTicks = t;
    lastMillis = millis();
  }
  fill(220);
  textSize(14);
  text("Pluck the string with the plectrum (red): drag it through the string slowly, or strum it.", 16, 24);
  text("Hold it on the string: palm mute.  Touch lightly a third of the way along: harmonic.", 16, 44);
  text("[ and ]: sphere of action (" + nf(sphere, 1, 2) + ")   UP / DOWN: volume (" + nf(volume, 1, 0)
    + ")   SPACE: pluck it for you   R: still the string", 16, 64);
  text(String.format("force on the handle %.2f N   haptic loop %.0f Hz   audio %.0f Hz", Math.hypot(force[0], force[1]),
    loopRate, out.sampleRate()), 16, height - 34);
  haptics.drawStatus();   // which board, or that the mouse is the hand (and why the loop stopped, if it did)
}

// Lifts the string into a triangle of the given height with its apex at mass 'at', and lets it go.
void pluck(int at, float height) {
  for (int i = 1; i <= masses; i++) {
    float y = i <= at ? height * i / at : height * (masses + 1 - i) / (masses + 1 - at);
    mdl.setMatPosition("m" + i, new Vect3D(i * spacing, y, 0));
  }
}

void keyPressed() {
  if (key == '[' || key == ']') {
    sphere = constrain(sphere + (key == ']' ? 0.01 : -0.01), 0.02, 0.3);
    mdl.setLinkParamsForName("pick", contactK, contactZ, sphere);
    renderer.setSize(matModuleType.HapticInput3D, sphere);
  } else if (key == ' ') {
    pluck(int(random(3, masses - 2)), 0.03);
  } else if (key == 'r' || key == 'R') {
    pluck(1, 0);
  } else if (keyCode == UP || keyCode == DOWN) {
    volume = constrain(volume * (keyCode == UP ? 1.25 : 0.8), 1, 300);
    ear.setGain(volume);
  }
}
