// simhuman's web viewer: draws a scene and its humans from body poses (three.js r111, Z up as in
// MuJoCo), for a replay file (all frames inlined) or the live server (frames by Server-Sent
// Events, commands by POST). The page reports its state into #status's data attributes
// (ready, frame, fps, errors) so headless browser tests can read it from the DOM.
(function () {
  'use strict';
  var DATA = window.SIMHUMAN_DATA || {};
  var params = new URLSearchParams(window.location.search);
  var statusEl = document.getElementById('status');
  var errors = 0;

  function $(id) { return document.getElementById(id); }
  function reportError(msg) {
    errors += 1;
    statusEl.dataset.errors = String(errors);
    statusEl.dataset.lastError = String(msg).slice(0, 300);
    $('message').textContent = String(msg);
  }
  window.addEventListener('error', function (e) { reportError(e.message || 'script error'); });
  window.addEventListener('unhandledrejection', function (e) { reportError(e.reason); });
  var consoleError = console.error;
  console.error = function () {
    reportError(Array.prototype.join.call(arguments, ' '));
    consoleError.apply(console, arguments);
  };

  // ---- three.js scene --------------------------------------------------------------------
  var container = $('view');
  var renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  // Adaptive resolution: a software renderer (Chromium's SwiftShader) is bound by the pixels it
  // fills, so when the browser's animation callbacks fall below 30 per second the page draws
  // fewer of them (the canvas is scaled up to the window) and above 45 more again, between 0.5 and 1 (the device's own ratio,
  // at most 1). ?resolution=full keeps full resolution.
  var fullRatio = Math.min(1, window.devicePixelRatio || 1);
  var adaptive = params.get('resolution') !== 'full';
  var pixelRatio = fullRatio;
  renderer.setPixelRatio(pixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  container.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0x9cc4e4);
  var camera = new THREE.PerspectiveCamera(50, window.innerWidth / window.innerHeight, 0.05, 200);
  camera.up.set(0, 0, 1);
  camera.position.set(3.5, -3.5, 2.6);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.set(0, 0, 0.8);
  controls.update();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667766, 0.75));
  var sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(3, -4, 8);
  scene.add(sun);
  // The page draws only when what it shows changed (a new pose, targets, the camera, the
  // window): a software renderer then spends its core on the frames the simulation streams
  // (30 Hz) and none on redrawing the same picture, and leaves the rest to the simulation
  // sharing the machine.
  var dirty = true;
  function redraw() { dirty = true; }
  controls.addEventListener('change', redraw);
  window.addEventListener('resize', function () {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    redraw();
  });

  var hideHumans = params.get('hide') === 'humans';
  var bodies = [];        // every drawn body: {group, moving, agent}
  var movingGroups = [];  // the groups of moving bodies, in pose-block order
  var followBody = null;  // the first human's first body (its pelvis)

  function material(rgba) {
    var m = new THREE.MeshLambertMaterial({ color: new THREE.Color(rgba[0], rgba[1], rgba[2]) });
    if (rgba[3] < 1) { m.transparent = true; m.opacity = rgba[3]; }
    return m;
  }
  function geomObject(g) {
    var s = g.size, mat = material(g.rgba), obj;
    if (g.type === 'box') {
      obj = new THREE.Mesh(new THREE.BoxBufferGeometry(2 * s[0], 2 * s[1], 2 * s[2]), mat);
    } else if (g.type === 'sphere') {
      obj = new THREE.Mesh(new THREE.SphereBufferGeometry(s[0], 16, 12), mat);
    } else if (g.type === 'ellipsoid') {
      obj = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 16, 12), mat);
      obj.scale.set(s[0], s[1], s[2]);
    } else if (g.type === 'cylinder' || g.type === 'capsule') {
      var cyl = new THREE.CylinderBufferGeometry(s[0], s[0], 2 * s[1], 16);
      cyl.rotateX(Math.PI / 2);  // three's cylinders lie along y, MuJoCo's along z
      obj = new THREE.Mesh(cyl, mat);
      if (g.type === 'capsule') {
        var cap = new THREE.SphereBufferGeometry(s[0], 12, 8);
        [-1, 1].forEach(function (side) {
          var end = new THREE.Mesh(cap, mat);
          end.position.set(0, 0, side * s[1]);
          obj.add(end);
        });
      }
    } else if (g.type === 'mesh') {
      // flat-shaded triangles: each face's three corners on their own
      var pos = new Float32Array(3 * g.faces.length);
      g.faces.forEach(function (v, i) {
        for (var k = 0; k < 3; ++k) pos[3 * i + k] = g.vertices[3 * v + k];
      });
      var geo = new THREE.BufferGeometry();
      geo.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      geo.computeVertexNormals();
      obj = new THREE.Mesh(geo, mat);
    } else if (g.type === 'plane') {
      var group = new THREE.Group();
      var floorMat = new THREE.MeshLambertMaterial({ color: 0xd8d2c4 });
      group.add(new THREE.Mesh(new THREE.PlaneBufferGeometry(2 * s[0], 2 * s[1]), floorMat));
      var grid = new THREE.GridHelper(2 * Math.min(s[0], s[1]), 2 * Math.min(s[0], s[1]),
                                      0x999080, 0xb8b0a0);
      grid.rotation.x = Math.PI / 2;  // the helper lies in x-z
      grid.position.z = 0.002;
      group.add(grid);
      obj = group;
    } else {
      return null;
    }
    obj.position.set(g.pos[0], g.pos[1], g.pos[2]);
    obj.quaternion.set(g.quat[1], g.quat[2], g.quat[3], g.quat[0]);
    return obj;
  }
  function buildScene(view) {
    view.bodies.forEach(function (b) {
      var group = new THREE.Group();
      b.geoms.forEach(function (g) {
        var o = geomObject(g);
        if (o) group.add(o);
      });
      group.position.set(b.pos[0], b.pos[1], b.pos[2]);
      group.quaternion.set(b.quat[1], b.quat[2], b.quat[3], b.quat[0]);
      group.visible = !(hideHumans && b.agent >= 0);
      scene.add(group);
      bodies.push({ group: group, moving: b.moving, agent: b.agent });
      if (b.moving) movingGroups.push(group);
      if (b.agent === 0 && !followBody) followBody = group;
    });
    statusEl.dataset.bodies = String(bodies.length);
    statusEl.dataset.moving = String(movingGroups.length);
    if (followBody) {
      controls.target.set(followBody.position.x, followBody.position.y, 0.8);
      camera.position.set(followBody.position.x + 3.2, followBody.position.y - 3.2, 2.4);
      controls.update();
    }
    redraw();
  }

  // contact targets: a red ball at each target, a line from the body point to it
  var kMaxTargets = 32;
  var targetBalls = [];
  var ballGeom = new THREE.SphereBufferGeometry(0.04, 10, 8);
  var ballMat = new THREE.MeshBasicMaterial({ color: 0xe02020 });
  for (var i = 0; i < kMaxTargets; i++) {
    var ball = new THREE.Mesh(ballGeom, ballMat);
    ball.visible = false;
    scene.add(ball);
    targetBalls.push(ball);
  }
  var lineGeom = new THREE.BufferGeometry();
  var linePos = new Float32Array(kMaxTargets * 6);
  lineGeom.setAttribute('position', new THREE.BufferAttribute(linePos, 3));
  var lines = new THREE.LineSegments(lineGeom, new THREE.LineBasicMaterial({ color: 0xe02020 }));
  lines.frustumCulled = false;
  scene.add(lines);
  function showTargets(arr, start, count) {
    count = Math.min(count, kMaxTargets);
    for (var k = 0; k < kMaxTargets; k++) {
      var on = k < count;
      targetBalls[k].visible = on;
      if (!on) continue;
      var o = start + 6 * k;
      targetBalls[k].position.set(arr[o + 3], arr[o + 4], arr[o + 5]);
      for (var c = 0; c < 6; c++) linePos[6 * k + c] = arr[o + c];
    }
    lineGeom.setDrawRange(0, 2 * count);
    lineGeom.attributes.position.needsUpdate = true;
    redraw();
  }

  var lastFollow = null;
  function applyPoses(arr, start) {
    redraw();
    for (var k = 0; k < movingGroups.length; k++) {
      var o = start + 7 * k, g = movingGroups[k];
      g.position.set(arr[o], arr[o + 1], arr[o + 2]);
      g.quaternion.set(arr[o + 4], arr[o + 5], arr[o + 6], arr[o + 3]);
    }
    if (followBody && $('follow').checked) {
      var p = followBody.position;
      if (lastFollow) {
        var dx = p.x - lastFollow.x, dy = p.y - lastFollow.y;
        controls.target.x += dx; controls.target.y += dy;
        camera.position.x += dx; camera.position.y += dy;
      } else {  // the first pose shown: frame the human from the front-side
        controls.target.set(p.x, p.y, 0.7);
        camera.position.set(p.x + 2.4, p.y - 2.4, 1.9);
      }
      lastFollow = { x: p.x, y: p.y };
    }
  }

  function decodeFloats(b64) {
    var bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (var k = 0; k < bin.length; k++) bytes[k] = bin.charCodeAt(k);
    return new Float32Array(bytes.buffer);
  }

  // plan steps: the list, the current one in bold, the text above it
  var stepTexts = [];
  function showSteps(texts) {
    stepTexts = texts || [];
    var ol = $('steps');
    ol.innerHTML = '';
    stepTexts.forEach(function (t) {
      var li = document.createElement('li');
      li.textContent = t;
      ol.appendChild(li);
    });
  }
  function showStep(step, extra) {
    var n = stepTexts.length;
    var items = $('steps').children;
    for (var k = 0; k < items.length; k++) {
      items[k].className = k < step ? 'done' : (k === step ? 'current' : '');
    }
    $('step').textContent = n ? 'step ' + (Math.min(step, n - 1) + 1) + '/' + n + ': ' +
        stepTexts[Math.min(step, n - 1)] + (extra || '') : (extra || 'no plan');
  }

  // ---- the render loop and its fps --------------------------------------------------------
  var playing = params.get('pause') !== '1';
  // fps: frames drawn per second (new content only); ticks: the browser's animation callbacks
  // per second, which fall below 30 when the drawing cannot keep up
  var fpsCount = 0, tickCount = 0, fpsT0 = performance.now();
  var onTick = function () {};
  function loop(now) {
    onTick(now);
    controls.update();
    tickCount += 1;
    if (dirty) {
      dirty = false;
      renderer.render(scene, camera);
      fpsCount += 1;
    }
    if (now - fpsT0 >= 1000) {
      var fps = fpsCount * 1000 / (now - fpsT0);
      var ticks = tickCount * 1000 / (now - fpsT0);
      statusEl.dataset.fps = fps.toFixed(1);
      statusEl.dataset.ticks = ticks.toFixed(1);
      $('fps').textContent = fps.toFixed(0) + ' fps' +
          (pixelRatio < fullRatio ? ' at ' + Math.round(100 * pixelRatio / fullRatio) + ' %' : '');
      if (adaptive) {
        var next = pixelRatio;
        if (ticks < 30 && pixelRatio > 0.5 * fullRatio) next = Math.max(0.5 * fullRatio, pixelRatio - 0.125);
        if (ticks > 45 && pixelRatio < fullRatio) next = Math.min(fullRatio, pixelRatio + 0.125);
        if (next !== pixelRatio) {
          pixelRatio = next;
          renderer.setPixelRatio(pixelRatio);
          renderer.setSize(window.innerWidth, window.innerHeight);
          redraw();
        }
        statusEl.dataset.pixelRatio = pixelRatio.toFixed(3);
      }
      fpsCount = 0; tickCount = 0; fpsT0 = now;
    }
    requestAnimationFrame(loop);
  }
  $('play').addEventListener('click', function () { setPlaying(!playing); });
  window.addEventListener('keydown', function (e) {
    if (e.code === 'Space' && document.activeElement !== $('command')) {
      setPlaying(!playing);
      e.preventDefault();
    }
  });
  var onPlayChange = function () {};
  function setPlaying(p) {
    playing = p;
    $('play').textContent = playing ? 'pause' : 'play';
    onPlayChange(p);
  }

  // ---- replay: every frame is in the file -------------------------------------------------
  function startReplay(d) {
    document.body.className = 'replay';
    var r = d.replay;
    var poses = decodeFloats(r.poses);
    var targets = r.targets ? decodeFloats(r.targets) : new Float32Array(0);
    var nFrames = r.times.length;
    var stride = 7 * movingGroups.length;
    var timeline = $('timeline');
    timeline.max = String(Math.max(0, nFrames - 1));
    var t = Math.max(0, parseFloat(params.get('t') || '0') || 0);
    var lastNow = null, frame = -1;
    function show(f) {
      frame = f;
      applyPoses(poses, f * stride);
      var from = r.target_offsets[f], to = r.target_offsets[f + 1];
      showTargets(targets, from * 6, to - from);
      showStep(r.steps[f]);
      $('time').textContent = r.times[f].toFixed(2) + ' s';
      timeline.value = String(f);
      statusEl.dataset.frame = String(f);
    }
    timeline.addEventListener('input', function () {
      t = r.times[parseInt(timeline.value, 10)] - r.times[0];
      show(parseInt(timeline.value, 10));
    });
    var duration = r.times[nFrames - 1] - r.times[0];
    onTick = function (now) {
      var dt = lastNow === null ? 0 : Math.min(0.1, (now - lastNow) / 1000);
      lastNow = now;
      if (playing) t += dt * parseFloat($('speed').value);
      if (t > duration + 1.0) t = 0;  // loop, after a second on the last frame
      var f = Math.min(nFrames - 1, Math.max(0, Math.round(t * r.fps)));
      if (f !== frame) show(f);
    };
    show(Math.min(nFrames - 1, Math.round(t * r.fps)));
    if (d.result) {
      $('message').textContent = (d.result.success ? 'plan succeeded' : 'plan did not succeed') +
          ' (' + d.result.end_reason + ')';
      $('message').style.color = d.result.success ? '#262' : '#a00';
    }
  }

  // ---- live: frames by Server-Sent Events, commands by POST -------------------------------
  function startLive(d) {
    document.body.className = 'live';
    var api = d.api || '/api';
    var token = null;
    var box = $('command');
    function post(path, body) {
      body = body || {};
      if (token) body.token = token;
      return fetch(api + path, { method: 'POST', headers: { 'Content-Type': 'application/json' },
                                 body: JSON.stringify(body) })
          .then(function (res) {
            return res.json().catch(function () { return {}; }).then(function (j) {
              if (!res.ok) throw new Error(j.error || ('HTTP ' + res.status));
              return j;
            });
          });
    }
    function setDriver(isDriver) {
      box.disabled = !isDriver;
      $('send').disabled = !isDriver;
      $('reset').disabled = !isDriver;
      $('role').textContent = isDriver ? 'you drive' : 'watching (another tab drives)';
      statusEl.dataset.role = isDriver ? 'driver' : 'watcher';
    }
    function claim() {
      return post('/drive').then(function (j) { token = j.token; setDriver(true); },
                                 function () { token = null; setDriver(false); });
    }
    function send() {
      var text = box.value.trim();
      if (!text) return Promise.resolve();
      var path = state.question ? '/answer' : '/command';
      $('message').textContent = '';
      statusEl.dataset.sent = String(parseInt(statusEl.dataset.sent || '0', 10) + 1);
      return post(path, { text: text }).then(function () { box.value = ''; },
        function (e) { $('message').style.color = '#a00'; $('message').textContent = e.message; });
    }
    $('send').addEventListener('click', send);
    box.addEventListener('keydown', function (e) { if (e.key === 'Enter') send(); });
    $('reset').addEventListener('click', function () { post('/reset').catch(reportError); });
    onPlayChange = function (p) { if (token) post('/pause', { paused: !p }).catch(function () {}); };
    window.simhuman = { send: function (text) { box.value = text; return send(); } };

    var state = {};
    function showState(s) {
      state = s;
      showSteps(s.steps);
      $('question').textContent = s.question ? s.question + ' (type your answer)' : '';
      $('message').style.color = s.state === 'error' ? '#a00' : '#333';
      $('message').textContent = s.message || '';
      box.placeholder = s.question ? 'your answer' : 'type a command, e.g. sit on the chair';
      statusEl.dataset.state = s.state;
      statusEl.dataset.plan = String(s.plan);
      if (s.paused !== undefined && s.paused === playing) {
        playing = !s.paused;
        $('play').textContent = playing ? 'pause' : 'play';
      }
    }
    var frames = 0;
    fetch(api + '/scene').then(function (res) { return res.json(); }).then(function (view) {
      $('title').textContent = view.title || 'simhuman live';
      buildScene(view.scene);
      var es = new EventSource(api + '/events');
      es.addEventListener('status', function (e) { showState(JSON.parse(e.data)); });
      es.addEventListener('frame', function (e) {
        var f = JSON.parse(e.data);
        applyPoses(decodeFloats(f.poses), 0);
        var tg = f.targets ? decodeFloats(f.targets) : new Float32Array(0);
        showTargets(tg, 0, tg.length / 6);
        showStep(f.step, state.state === 'running' ? '' : ' (' + (state.state || '') + ')');
        if (!state.steps || !state.steps.length) showStep(0, state.state || 'idle');
        $('time').textContent = f.t.toFixed(2) + ' s';
        frames += 1;
        statusEl.dataset.frame = String(frames);
        statusEl.dataset.simTime = f.t.toFixed(3);
      });
      es.onerror = function () { $('role').textContent = 'disconnected, retrying...'; };
      return claim();
    }).then(function () {
      statusEl.dataset.ready = '1';
      setInterval(function () {
        var fps = parseFloat(statusEl.dataset.fps);
        if (token) post('/drive', { fps: isFinite(fps) ? fps : 0 }).catch(function () { claim(); });
      }, 3000);
      var cmd = params.get('command');  // test hook: type this command into the box and send it
      if (cmd && token) window.simhuman.send(cmd);
    }).catch(reportError);
  }

  if (DATA.mode === 'replay') {
    $('title').textContent = DATA.title || 'simhuman replay';
    buildScene(DATA.scene);
    showSteps(DATA.steps);
    startReplay(DATA);
    statusEl.dataset.ready = '1';
  } else if (DATA.mode === 'live') {
    startLive(DATA);
  } else {
    reportError('no data: this page is made by simhuman replay --html or simhuman serve');
  }
  setPlaying(playing);
  requestAnimationFrame(loop);
})();
