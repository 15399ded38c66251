// SPDX-License-Identifier: GPL-3.0-or-later
// The page's style and scripts (src/page_assets.h): no framework, nothing fetched.
#include "page_assets.h"

namespace lepp::html::detail {

const char* const kStyle = R"CSS(
body{font:15px/1.45 system-ui,sans-serif;margin:0 auto;max-width:1200px;padding:0 18px 40px;color:#111}
h1{font-size:1.5em;margin:18px 0 6px}h2{font-size:1.2em;margin:26px 0 8px;border-bottom:1px solid #ccc}
h3{font-size:1.05em;margin:18px 0 6px}
table{border-collapse:collapse;margin:6px 0 12px}td,th{border:1px solid #ccc;padding:3px 8px;text-align:left;vertical-align:top}
td.n,th.n{text-align:right;font-variant-numeric:tabular-nums}
.ok{color:#0a6b2d}.bad{color:#b00020}.verdict{font-size:1.2em;font-weight:600}
code,pre{font:13px/1.35 ui-monospace,monospace;background:#f4f4f4}pre{padding:6px 8px;overflow-x:auto;white-space:pre-wrap}
figure{margin:8px 0;display:inline-block;vertical-align:top}figcaption{font-size:13px;color:#444;max-width:640px}
.pz{border:1px solid #bbb;overflow:hidden;cursor:grab;background:#fff;touch-action:none}
.pz svg{display:block;max-width:100%;height:auto}.pz img{display:block;max-width:100%;height:auto}
figure.overview .pz svg{width:900px}figure.zoom .pz svg{width:340px}figure.step .pz svg{width:520px}
.violation,.finding{border-left:3px solid #b00020;padding:2px 0 2px 10px;margin:10px 0}
.violation{display:flex;gap:14px;align-items:flex-start}.violation figure{margin:0;flex:none}
.violation .words{min-width:0;flex:1}.violation p{margin:4px 0}.coords{font-size:12px}
details>summary{cursor:pointer;color:#0645ad;margin:6px 0}
button.copy{font-size:12px;margin-left:6px}.wide{overflow-x:auto}
#page-errors:empty{display:none}#page-errors{color:#b00020;border:2px solid #b00020;padding:4px 24px}
)CSS";

const char* const kErrorHook = R"JS(
(function(){
  var pending=[];
  function list(){return document.getElementById('page-errors');}
  function add(text){
    var l=list();
    if(!l){pending.push(text);return;}
    var li=document.createElement('li');li.textContent=text;l.appendChild(li);
  }
  window.addEventListener('error',function(e){
    var t=e.target;
    if(t&&t!==window&&(t.src||t.href))add('failed to load '+(t.src||t.href).slice(0,120));
    else add('script error: '+e.message+' at line '+e.lineno);
  },true);
  window.addEventListener('unhandledrejection',function(e){add('unhandled rejection: '+e.reason);});
  var original=console.error;
  console.error=function(){add('console.error: '+Array.prototype.join.call(arguments,' '));return original.apply(console,arguments);};
  document.addEventListener('DOMContentLoaded',function(){pending.forEach(add);pending=[];});
})();
)JS";

const char* const kScript = R"JS(
(function(){
  // Pan (drag) and zoom (wheel, around the pointer) by changing the viewBox; double-click resets.
  function panZoom(frame){
    var svg=frame.querySelector('svg');if(!svg||!svg.viewBox||!svg.viewBox.baseVal)return;
    var vb=svg.viewBox.baseVal,home=[vb.x,vb.y,vb.width,vb.height],drag=null;
    function toView(e){var r=svg.getBoundingClientRect();return[vb.x+(e.clientX-r.left)/r.width*vb.width,vb.y+(e.clientY-r.top)/r.height*vb.height];}
    frame.addEventListener('wheel',function(e){
      e.preventDefault();var p=toView(e),k=Math.exp(e.deltaY*0.0015);
      vb.x=p[0]-(p[0]-vb.x)*k;vb.y=p[1]-(p[1]-vb.y)*k;vb.width*=k;vb.height*=k;
    },{passive:false});
    frame.addEventListener('pointerdown',function(e){drag={x:e.clientX,y:e.clientY,vx:vb.x,vy:vb.y};frame.setPointerCapture(e.pointerId);frame.style.cursor='grabbing';});
    frame.addEventListener('pointermove',function(e){
      if(!drag)return;var r=svg.getBoundingClientRect();
      vb.x=drag.vx-(e.clientX-drag.x)/r.width*vb.width;vb.y=drag.vy-(e.clientY-drag.y)/r.height*vb.height;
    });
    function end(){drag=null;frame.style.cursor='';}
    frame.addEventListener('pointerup',end);frame.addEventListener('pointercancel',end);
    frame.addEventListener('dblclick',function(){vb.x=home[0];vb.y=home[1];vb.width=home[2];vb.height=home[3];});
  }
  // The copy buttons: the text of the element named by data-copy to the clipboard.
  function copyButton(b){
    b.addEventListener('click',function(){
      var t=document.getElementById(b.dataset.copy);if(!t)return;
      if(navigator.clipboard)navigator.clipboard.writeText(t.textContent).then(function(){b.textContent='copied';},function(){});
    });
  }
  // #check: every <details> open, each picture's place and size written on it, the load time on <body>.
  function check(){
    document.querySelectorAll('details').forEach(function(d){d.open=true;});
    document.querySelectorAll('.picture').forEach(function(p){
      var r=(p.firstElementChild||p).getBoundingClientRect();  // the drawing itself, not its frame
      p.dataset.x=Math.round(r.left+window.scrollX);p.dataset.y=Math.round(r.top+window.scrollY);
      p.dataset.w=Math.round(r.width);p.dataset.h=Math.round(r.height);
    });
    document.body.dataset.height=Math.ceil(document.documentElement.scrollHeight);
    document.body.dataset.width=Math.ceil(document.documentElement.scrollWidth);
  }
  window.addEventListener('load',function(){
    document.querySelectorAll('.pz').forEach(panZoom);
    document.querySelectorAll('button.copy').forEach(copyButton);
    if(location.hash==='#check')check();
    document.body.dataset.loadMs=Math.round(performance.now());
    document.body.dataset.ready='1';
  });
})();
)JS";

}  // namespace lepp::html::detail
